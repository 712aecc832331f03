// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors

#include "integrators/integrator_registry.h"

#include <stdexcept>

namespace stipple::render {

namespace {

using Factory = std::unique_ptr<Integrator> (*)(const RenderScene&, const Camera&, const IntegratorSettings&,
                                                const std::string& name);

struct Entry {
    const char* name;
    Factory make;
};

// The one list of integrators: names for help texts and validation come from here.
const Entry kIntegrators[] = {
    {"path", [](const RenderScene& s, const Camera&, const IntegratorSettings& o,
                const std::string&) { return makePathIntegrator(s, o); }},
    {"direct", [](const RenderScene& s, const Camera&, const IntegratorSettings& o,
                  const std::string&) { return makeDirectIntegrator(s, o, DirectStrategy::Mis); }},
    {"direct-light", [](const RenderScene& s, const Camera&, const IntegratorSettings& o,
                        const std::string&) { return makeDirectIntegrator(s, o, DirectStrategy::LightOnly); }},
    {"direct-bsdf", [](const RenderScene& s, const Camera&, const IntegratorSettings& o,
                       const std::string&) { return makeDirectIntegrator(s, o, DirectStrategy::BsdfOnly); }},
    {"bdpt", makeBdptIntegrator},
};

// "bdpt:..." selects BDPT's debug variants (bdpt_integrator.h).
bool isBdptVariant(const std::string& name) { return name.rfind("bdpt:", 0) == 0; }

} // namespace

std::vector<std::string> registeredIntegrators() {
    std::vector<std::string> names;
    for (const Entry& e : kIntegrators) names.push_back(e.name);
    return names;
}

std::string knownIntegrators() {
    std::string list;
    for (const Entry& e : kIntegrators) list += (list.empty() ? "" : ", ") + std::string(e.name);
    return list + " (debug: bdpt:s=S,t=T[,mis], bdpt:depth=D)";
}

std::unique_ptr<Integrator> makeIntegrator(const std::string& name, const RenderScene& scene, const Camera& camera,
                                           const IntegratorSettings& settings) {
    if (isBdptVariant(name)) return makeBdptIntegrator(scene, camera, settings, name);
    for (const Entry& e : kIntegrators)
        if (name == e.name) return e.make(scene, camera, settings, name);
    throw std::invalid_argument("unknown integrator '" + name + "'; expected one of " + knownIntegrators());
}

} // namespace stipple::render
