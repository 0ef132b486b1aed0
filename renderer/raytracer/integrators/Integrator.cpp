#include "integrators/Integrator.h"

#include "integrators/DirectLightingIntegrator.h"
#include "integrators/PathIntegrator.h"

namespace lenslab {

std::unique_ptr<Integrator> makeIntegrator(const SceneGeometry& geometry, const IntegratorSpec& spec) {
    switch (spec.type) {
        case IntegratorType::DirectLighting:
            return std::make_unique<DirectLightingIntegrator>(geometry, spec.maxDepth, LightSampleWeight::Mis);
        case IntegratorType::Whitted:
            return std::make_unique<DirectLightingIntegrator>(geometry, spec.maxDepth, LightSampleWeight::Alone);
        case IntegratorType::Path:
            break;
    }
    return std::make_unique<PathIntegrator>(geometry, spec.maxDepth);
}

}  // namespace lenslab
