#include "integrators/Integrator.h"

#include "integrators/DirectLightingIntegrator.h"
#include "integrators/PathIntegrator.h"
#include "integrators/VolPathIntegrator.h"

namespace lenslab {

std::unique_ptr<Integrator> makeIntegrator(const SceneGeometry& geometry, const IntegratorSpec& spec,
                                           const ParticipatingMedium* cameraMedium) {
    switch (spec.type) {
        case IntegratorType::DirectLighting:
            return std::make_unique<DirectLightingIntegrator>(geometry, spec.maxDepth, LightSampleWeight::Mis);
        case IntegratorType::Whitted:
            return std::make_unique<DirectLightingIntegrator>(geometry, spec.maxDepth, LightSampleWeight::Alone);
        case IntegratorType::VolPath:
            return std::make_unique<VolPathIntegrator>(geometry, spec.maxDepth, cameraMedium);
        case IntegratorType::Path:
            break;
    }
    return std::make_unique<PathIntegrator>(geometry, spec.maxDepth);
}

}  // namespace lenslab
