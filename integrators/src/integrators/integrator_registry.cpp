#include "integrators/integrator_registry.h"

#include <stdexcept>

namespace stipple::render {

std::string knownIntegrators() {
#ifdef STIPPLE_HAVE_BDPT
    return "path, direct, direct-light, direct-bsdf, bdpt (debug: bdpt:s=S,t=T[,mis], bdpt:depth=D)";
#else
    return "path, direct, direct-light, direct-bsdf";
#endif
}

std::unique_ptr<Integrator> makeIntegrator(const std::string& name, const RenderScene& scene, const Camera& camera,
                                           const IntegratorSettings& settings) {
    (void)camera;
    if (name == "path") return makePathIntegrator(scene, settings);
    if (name == "direct") return makeDirectIntegrator(scene, settings, DirectStrategy::Mis);
    if (name == "direct-light") return makeDirectIntegrator(scene, settings, DirectStrategy::LightOnly);
    if (name == "direct-bsdf") return makeDirectIntegrator(scene, settings, DirectStrategy::BsdfOnly);
#ifdef STIPPLE_HAVE_BDPT
    if (name == "bdpt" || name.rfind("bdpt:", 0) == 0) return makeBdptIntegrator(scene, camera, settings, name);
#endif
    throw std::invalid_argument("unknown integrator '" + name + "'; expected one of " + knownIntegrators());
}

} // namespace stipple::render
