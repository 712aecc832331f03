// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// Small repeated details, each one prototype instanced many times: balconies, chimneys, street lamps, and the
// piazza's fountain. Each is a list of (material, mesh) parts in its own coordinates.
#pragma once

#include "mesh.h"

#include <string>
#include <utility>
#include <vector>

namespace stipple::citygen {

struct DetailPrototype {
    std::string name;
    std::vector<std::pair<std::string, Mesh>> parts; // material name -> mesh
};

// Origin on the facade at floor level, +z out of the wall.
DetailPrototype makeBalcony();
// Origin at the centre of the base (which sits below the roof surface), +y up.
DetailPrototype makeChimney();
// Origin at the foot of the post, the arm and lantern towards +z.
DetailPrototype makeStreetLamp();
// Origin at the centre of the basin on the ground.
DetailPrototype makeFountain();

} // namespace stipple::citygen
