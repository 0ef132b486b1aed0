#pragma once
// Measured isotropic BRDFs read from files, as pbrt's "measured" material reads them:
//  - ".brdf": Cornell's irregularly sampled spectral text format (pbrt's scenes/brdfs): the number
//    of wavelengths, the wavelengths in nm, then one record per measurement: theta_i phi_i
//    theta_o phi_o (radians) and one BRDF value per wavelength; '#' starts a comment.
//  - anything else: a MERL BRDF database binary (Matusik et al. 2003): three 32-bit integers
//    90 90 180, then 90*90*180 doubles for red, the same for green and blue, indexed by
//    (sqrt-spaced theta_half, theta_diff, phi_diff).
#include <memory>
#include <string>

#include "materials/Bsdf.h"
#include "core/ParamSet.h"

namespace lenslab {

class MeasuredBrdf {
public:
    virtual ~MeasuredBrdf() = default;
    virtual Vec3f f(Vec3f wo, Vec3f wi) const = 0;  // local shading frame
};

// `path` is already resolved; `name` is how the scene wrote it. Bad files fail via params.fail.
// Chooses the reader by the file name's suffix, as pbrt does.
std::shared_ptr<const MeasuredBrdf> loadMeasuredBrdf(const std::string& path, const std::string& name,
                                                     const ParamSet& params);
std::shared_ptr<const MeasuredBrdf> loadIrregularBrdf(const std::string& path, const std::string& name,
                                                      const ParamSet& params);
std::shared_ptr<const MeasuredBrdf> loadMerlBrdf(const std::string& path, const std::string& name,
                                                 const ParamSet& params);

// The lobe of a measured material: the table's value, sampled cosine-weighted (the table gives
// no better density). Weight: the mix share.
class MeasuredLobe final : public Lobe {
public:
    explicit MeasuredLobe(const MeasuredBrdf* brdf) : brdf_(brdf) {}
    unsigned type() const override { return kReflection; }
    Vec3f f(Vec3f wo, Vec3f wi) const override { return brdf_->f(wo, wi); }

private:
    const MeasuredBrdf* brdf_;
};

}  // namespace lenslab
