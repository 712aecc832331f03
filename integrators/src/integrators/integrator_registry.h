// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// Factories of the integrators makeIntegrator knows.
#pragma once

#include "integrators/integrator.h"

namespace stipple::render {

std::unique_ptr<Integrator> makePathIntegrator(const RenderScene& scene, const IntegratorSettings& settings);

enum class DirectStrategy { Mis, LightOnly, BsdfOnly };
std::unique_ptr<Integrator> makeDirectIntegrator(const RenderScene& scene, const IntegratorSettings& settings,
                                                 DirectStrategy strategy);

// `name` is "bdpt" or a debug variant "bdpt:..." (integrators/bdpt/bdpt_integrator.h).
std::unique_ptr<Integrator> makeBdptIntegrator(const RenderScene& scene, const Camera& camera,
                                               const IntegratorSettings& settings, const std::string& name);

} // namespace stipple::render
