// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// Pitched (gable) and hip roofs covered with rows of barrel tiles (coppi), with ridge and hip rolls.
#pragma once

#include "building.h"

namespace stipple::citygen {

// Adds the roof of `spec` to parts.roof (and its gable walls to parts.wall).
void buildRoof(const BuildingSpec& spec, BuildingParts& parts);

// Height of the roof surface above the footprint point (x, z), building coordinates, for placing chimneys.
double roofHeightAt(const BuildingSpec& spec, double x, double z);

} // namespace stipple::citygen
