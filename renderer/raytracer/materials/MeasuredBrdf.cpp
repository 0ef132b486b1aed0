#include "materials/MeasuredBrdf.h"

namespace lenslab {

std::shared_ptr<const MeasuredBrdf> loadMeasuredBrdf(const std::string& path, const std::string& name,
                                                     const ParamSet& params) {
    const auto dot = name.rfind('.');
    const std::string suffix = dot == std::string::npos ? "" : name.substr(dot);
    if (suffix == ".brdf" || suffix == ".BRDF") return loadIrregularBrdf(path, name, params);
    return loadMerlBrdf(path, name, params);
}

}  // namespace lenslab
