// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// One building prototype: a block of storeys with window recesses, an optional ground-floor arcade,
// cornices and a tiled pitched or hip roof, split by material so the scene can colour it.
#pragma once

#include "mesh.h"
#include "rng.h"

#include <string>
#include <vector>

namespace stipple::citygen {

enum class RoofKind { Gable, Hip };

struct BuildingSpec {
    int baysX = 4;    // along the street (front facade, +z)
    int baysZ = 4;    // along the depth
    double bay = 3.2; // metres per bay
    int floors = 4;   // ground floor included
    double groundHeight = 4.4;
    double storeyHeight = 3.4;
    bool arcade = false; // ground floor of the front facade is a portico of arches
    bool belfry = false; // top storey opens in arches on all sides (the campanile)
    bool slitWindows = false;
    RoofKind roof = RoofKind::Gable;
    double pitchDegrees = 22;
    int balconies = 0; // on the first floor of the front
    int chimneys = 0;

    double width() const { return baysX * bay; }
    double depth() const { return baysZ * bay; }
    double height() const { return groundHeight + (floors - 1) * storeyHeight; }
};

// A detail placed in the building's own coordinates (footprint x in [0, W], z in [0, D], front at z = D):
// rotate by `yawDegrees` about +y, then translate to `position`.
struct DetailPlacement {
    std::string object;
    double yawDegrees = 0;
    Vec3 position;
};

struct BuildingParts {
    Mesh wall;    // plaster
    Mesh trim;    // stone: sills, lintels, cornices, arches
    Mesh glass;   // dark window panes and door voids
    Mesh shutter; // wooden shutters, doors, window frames
    Mesh roof;    // clay tiles
    std::vector<DetailPlacement> details;
};

BuildingParts buildBuilding(const BuildingSpec& spec, Rng& rng);

} // namespace stipple::citygen
