#include "materials/Pbrt4Materials.h"

#include <cmath>
#include <map>
#include <mutex>
#include <optional>

#include "materials/Bsdf.h"
#include "materials/DiffuseLobes.h"
#include "materials/HairMaterial.h"
#include "materials/MetalSpectra.h"
#include "core/MeasuredMedia.h"
#include "materials/MicrofacetLobes.h"
#include "materials/SpecularLobes.h"
#include "materials/SubsurfaceAlbedo.h"

namespace lenslab {

namespace {

// pbrt-v4's microfacet roughness: "roughness", or "uroughness"/"vroughness", remapped (by default)
// as alpha = sqrt(roughness); below alpha 1e-3 the surface is perfectly smooth.
struct Pbrt4Roughness {
    TexturePtr u, v;
    bool remap = true;

    MicrofacetDistribution at(const SurfaceHit& h) const {
        float au = u->evaluate(h).x, av = v->evaluate(h).x;
        if (remap) {
            au = std::sqrt(std::max(0.0f, au));
            av = std::sqrt(std::max(0.0f, av));
        }
        return {MicrofacetKind::TrowbridgeReitz, au, av};
    }
    bool smoothAt(const SurfaceHit& h) const {
        const float au = u->evaluate(h).x, av = v->evaluate(h).x;
        const float a = std::max(au, av);
        return (remap ? std::sqrt(std::max(0.0f, a)) : a) < 1e-3f;
    }
};

class Pbrt4Reader {
public:
    Pbrt4Reader(const ParamSet& p, const MaterialContext& c) : p_(p), c_(c) {}
    TexturePtr color(const std::string& name, Vec3f fallback) const { return textureParam(p_, name, fallback, c_.textures); }
    TexturePtr number(const std::string& name, float fallback) const { return floatTextureParam(p_, name, fallback, c_.textures); }
    // prefix: "" or coatedconductor's "interface." / "conductor.".
    Pbrt4Roughness roughness(const std::string& prefix = "") const {
        const TexturePtr r = number(prefix + "roughness", 0);
        const TexturePtr u = p_.has(prefix + "uroughness") ? number(prefix + "uroughness", 0) : r;
        const TexturePtr v = p_.has(prefix + "vroughness") ? number(prefix + "vroughness", 0) : r;
        return {u, v, p_.getBool("remaproughness", true)};
    }
    // An index of refraction: a number, or a spectrum (named glass, sampled) taken at its mean,
    // as lenslab renders without dispersion.
    float eta(const std::string& name, float fallback = 1.5f) const {
        const float eta = float(p_.has(name) && p_.isSpectral(name) ? p_.getRgb(name, grey(fallback)).y : p_.getFloat(name, fallback));
        if (!(eta > 0)) p_.fail("\"" + name + "\" (index of refraction) must be positive");
        if (p_.isSpectral(name)) warn("\"" + name + "\" is a spectrum: rendered at one index, " + std::to_string(eta) + " (no dispersion)");
        return eta;
    }
    // A conductor's complex index: eta and k (pbrt-v4's default: copper), or a "reflectance" colour
    // for which pbrt-v4 takes eta 1 and k = 2 sqrt(r) / sqrt(1 - r).
    struct Conductor {
        TexturePtr eta, k, reflectance;
    };
    Conductor conductor(const std::string& prefix) const {
        if (p_.has("reflectance")) {  // unprefixed in coatedconductor too
            if (p_.has(prefix + "eta") || p_.has(prefix + "k")) p_.fail("give \"reflectance\" or eta and k, not both");
            return {nullptr, nullptr, color("reflectance", grey(0))};
        }
        static const Vec3f copperEta = namedSpectrumRgb("metal-Cu-eta").value(), copperK = namedSpectrumRgb("metal-Cu-k").value();
        return {color(prefix + "eta", copperEta), color(prefix + "k", copperK), nullptr};
    }
    void warn(const std::string& message) const { c_.warnings.push_back(describe(p_.where()) + ": " + message); }
    const ParamSet& params() const { return p_; }

private:
    const ParamSet& p_;
    const MaterialContext& c_;
};

// The Fresnel factor of a conductor at a hit, seen from a medium of index outside.
Fresnel conductorFresnel(const Pbrt4Reader::Conductor& c, const SurfaceHit& h, float outside) {
    Vec3f eta, k;
    if (c.reflectance) {
        const Vec3f r = atLeastZero(c.reflectance->evaluate(h));
        const auto kOf = [](float v) {
            v = std::min(v, 0.9999f);
            return 2 * std::sqrt(v) / std::sqrt(1 - v);
        };
        eta = {1, 1, 1};
        k = {kOf(r.x), kOf(r.y), kOf(r.z)};
    } else {
        eta = c.eta->evaluate(h);
        k = c.k->evaluate(h);
    }
    return Fresnel::conductor(eta / outside, k / outside);
}

// Mirror-like or glossy reflection with a Fresnel factor, as the roughness at the hit says.
void addReflection(Bsdf& b, Vec3f weight, const Pbrt4Roughness& r, const SurfaceHit& h, Fresnel fresnel) {
    if (r.smoothAt(h)) b.add<SpecularReflection>(weight, fresnel);
    else b.add<MicrofacetReflection>(weight, r.at(h), fresnel);
}

class Diffuse final : public Material {
public:
    explicit Diffuse(TexturePtr r) : r_(std::move(r)) {}
    void addLobes(const SurfaceHit& h, Vec3f scale, Bsdf& b) const override {
        b.add<LambertianReflection>(scale * atLeastZero(r_->evaluate(h)));
    }
    int maxLobes() const override { return 1; }

private:
    TexturePtr r_;
};

class Conductor final : public Material {
public:
    Conductor(Pbrt4Reader::Conductor c, Pbrt4Roughness r) : c_(std::move(c)), r_(std::move(r)) {}
    void addLobes(const SurfaceHit& h, Vec3f scale, Bsdf& b) const override {
        addReflection(b, scale, r_, h, conductorFresnel(c_, h, 1.0f));
    }
    int maxLobes() const override { return 1; }

private:
    Pbrt4Reader::Conductor c_;
    Pbrt4Roughness r_;
};

class Dielectric final : public Material {
public:
    Dielectric(float eta, Pbrt4Roughness r) : eta_(eta), r_(std::move(r)) {}
    void addLobes(const SurfaceHit& h, Vec3f scale, Bsdf& b) const override {
        if (r_.smoothAt(h)) {
            b.add<FresnelSpecular>(scale, Vec3f{1, 1, 1}, Vec3f{1, 1, 1}, 1.0f, eta_);
            return;
        }
        const MicrofacetDistribution d = r_.at(h);
        b.add<MicrofacetReflection>(scale, d, Fresnel::dielectric(1.0f, eta_));
        b.add<MicrofacetTransmission>(scale, d, 1.0f, eta_);
    }
    int maxLobes() const override { return 2; }

private:
    float eta_;
    Pbrt4Roughness r_;
};

// pbrt-v4's subsurface: a dielectric boundary over a homogeneous scattering volume, rendered by
// the volumetric path tracer as a random walk inside it (docs/media.md). The coefficients come
// from sigma_a and sigma_s, a measured medium's name, or a reflectance and mean free path.
class Subsurface final : public Material {
public:
    struct Interior {
        TexturePtr sigmaA, sigmaS;         // given or named; else
        TexturePtr reflectance, mfp;       // inverted through the albedo table
        std::shared_ptr<const SubsurfaceAlbedoTable> table;
        float scale = 1, g = 0;
    };
    Subsurface(float eta, Pbrt4Roughness r, Interior interior) : boundary_(eta, std::move(r)), interior_(std::move(interior)) {}
    void addLobes(const SurfaceHit& h, Vec3f scale, Bsdf& b) const override { boundary_.addLobes(h, scale, b); }
    int maxLobes() const override { return boundary_.maxLobes(); }
    bool hasInterior() const override { return true; }
    InteriorMedium interiorAt(const SurfaceHit& h) const override {
        const Interior& in = interior_;
        if (in.sigmaA) return {in.scale * atLeastZero(in.sigmaA->evaluate(h)), in.scale * atLeastZero(in.sigmaS->evaluate(h)), in.g};
        const Vec3f r = atLeastZero(in.reflectance->evaluate(h)), mfp = in.scale * atLeastZero(in.mfp->evaluate(h));
        float albedo[3], sigmaT[3];
        for (int c = 0; c < 3; ++c) {
            // The table is for isotropic scattering: its albedo is the reduced one, a (1 - g) / (1 - a g).
            const float reduced = in.table->singleScatteringAlbedo(r[c]);
            albedo[c] = reduced / (1 - in.g + in.g * reduced);
            sigmaT[c] = 1 / std::max(mfp[c], 1e-30f);
        }
        const Vec3f a{albedo[0], albedo[1], albedo[2]}, t{sigmaT[0], sigmaT[1], sigmaT[2]};
        return {(Vec3f{1, 1, 1} - a) * t, a * t, in.g};
    }

private:
    Dielectric boundary_;
    Interior interior_;
};

class ThinDielectricMaterial final : public Material {
public:
    explicit ThinDielectricMaterial(float eta) : eta_(eta) {}
    void addLobes(const SurfaceHit&, Vec3f scale, Bsdf& b) const override { b.add<ThinDielectric>(scale, eta_); }
    int maxLobes() const override { return 1; }
    bool isSpecular() const override { return true; }

private:
    float eta_;
};

class DiffuseTransmission final : public Material {
public:
    DiffuseTransmission(TexturePtr r, TexturePtr t, float scale) : r_(std::move(r)), t_(std::move(t)), scale_(scale) {}
    void addLobes(const SurfaceHit& h, Vec3f scale, Bsdf& b) const override {
        b.add<LambertianReflection>(scale_ * scale * atLeastZero(r_->evaluate(h)));
        b.add<LambertianTransmission>(scale_ * scale * atLeastZero(t_->evaluate(h)));
    }
    int maxLobes() const override { return 2; }

private:
    TexturePtr r_, t_;
    float scale_;
};

// A dielectric coat (index eta, its own roughness) over a diffuse base (DiffuseLobes.h).
class CoatedDiffuseMaterial final : public Material {
public:
    CoatedDiffuseMaterial(TexturePtr reflectance, Pbrt4Roughness coat, float eta, float thickness)
        : reflectance_(std::move(reflectance)), coat_(std::move(coat)), eta_(eta), thickness_(thickness),
          internal_(coatInternalReflectance(eta)) {}
    void addLobes(const SurfaceHit& h, Vec3f scale, Bsdf& b) const override {
        addReflection(b, scale, coat_, h, Fresnel::coat(1.0f, eta_));
        const Vec3f r = atLeastZero(reflectance_->evaluate(h));
        b.add<CoatedDiffuse>(scale, Vec3f{std::min(r.x, 1.0f), std::min(r.y, 1.0f), std::min(r.z, 1.0f)}, eta_, thickness_, internal_);
    }
    int maxLobes() const override { return 2; }

private:
    TexturePtr reflectance_;
    Pbrt4Roughness coat_;
    float eta_, thickness_, internal_;
};

// A dielectric coat over a conductor: the coat's reflection, and the conductor's (its Fresnel
// factor seen from inside the coat) dimmed by passing the coat twice at normal incidence, without
// the bending of the directions inside or the layer's inter-reflections (docs/pbrt-v4.md).
class CoatedConductorMaterial final : public Material {
public:
    CoatedConductorMaterial(Pbrt4Roughness coat, float eta, float thickness, Pbrt4Reader::Conductor conductor, Pbrt4Roughness metal)
        : coat_(std::move(coat)), eta_(eta), conductor_(std::move(conductor)), metal_(std::move(metal)) {
        const float f0 = fresnelDielectric(1.0f, 1.0f, eta);
        through_ = (1 - f0) * (1 - f0) * std::exp(-2 * thickness);
    }
    void addLobes(const SurfaceHit& h, Vec3f scale, Bsdf& b) const override {
        addReflection(b, scale, coat_, h, Fresnel::coat(1.0f, eta_));
        addReflection(b, through_ * scale, metal_, h, conductorFresnel(conductor_, h, eta_));
    }
    int maxLobes() const override { return 2; }

private:
    Pbrt4Roughness coat_;
    float eta_;
    Pbrt4Reader::Conductor conductor_;
    Pbrt4Roughness metal_;
    float through_ = 1;
};

// The layer of coateddiffuse and coatedconductor: its thickness; pbrt-v4's random-walk settings
// (maxdepth, nsamples) have no meaning for a closed-form model, and its scattering is not simulated.
float layerThickness(const Pbrt4Reader& r) {
    const ParamSet& p = r.params();
    if (p.has("albedo") || p.has("g")) {
        r.warn("the coat's scattering (albedo, g) is not simulated; its absorption over the thickness is");
        r.color("albedo", grey(0));
        r.number("g", 0);
    }
    p.getInts("maxdepth");
    p.getInts("nsamples");
    const float t = float(r.params().getFloat("thickness", 0.01));
    if (!(t >= 0)) r.params().fail("thickness must not be negative");
    return t;
}

// One albedo table per index of refraction, computed once (SubsurfaceAlbedo.h).
std::shared_ptr<const SubsurfaceAlbedoTable> albedoTable(float eta) {
    static std::mutex mutex;
    static std::map<float, std::shared_ptr<const SubsurfaceAlbedoTable>> tables;
    const std::lock_guard<std::mutex> lock(mutex);
    auto& table = tables[eta];
    if (!table) table = std::make_shared<const SubsurfaceAlbedoTable>(eta);
    return table;
}

// pbrt-v4's four exclusive forms, in its order: "name", "sigma_a" with "sigma_s", "reflectance"
// (with "mfp", default 1), or pbrt's default coefficients (those of whole milk, per mm).
std::shared_ptr<Material> makeSubsurface(const Pbrt4Reader& r) {
    const ParamSet& p = r.params();
    Subsurface::Interior in;
    in.g = float(p.getFloat("g", 0));
    if (!(in.g > -1 && in.g < 1)) p.fail("g must lie in (-1, 1)");
    in.scale = float(p.getFloat("scale", 1));
    if (!(in.scale >= 0)) p.fail("scale must not be negative");
    const std::string name = p.getString("name", "");
    if (!name.empty()) {
        const std::optional<MeasuredMedium> m = measuredMedium(name);
        if (!m) p.fail("no measured medium is named \"" + name + "\" (docs/media.md lists them)");
        if (in.g != 0) r.warn("\"g\" is ignored with a named medium: its scattering coefficients are reduced ones (g 0)");
        in.g = 0;
        in.sigmaA = makeConstantTexture(m->sigmaA);
        in.sigmaS = makeConstantTexture(m->sigmaSPrime);
    } else if (p.has("sigma_a") || p.has("sigma_s")) {
        if (!p.has("sigma_a") || !p.has("sigma_s")) p.fail("give both \"sigma_a\" and \"sigma_s\"");
        for (const char* n : {"sigma_a", "sigma_s"}) {
            const ColorOrTexture c = p.getColorOrTexture(n, {});
            if (!c.texture && !(c.color.x >= 0 && c.color.y >= 0 && c.color.z >= 0)) p.fail(std::string(n) + " must not be negative");
        }
        in.sigmaA = r.color("sigma_a", {});
        in.sigmaS = r.color("sigma_s", {});
    } else if (p.has("reflectance")) {
        in.reflectance = r.color("reflectance", {});
        in.mfp = r.color("mfp", grey(1));
    } else {
        in.sigmaA = makeConstantTexture({0.0011f, 0.0024f, 0.014f});
        in.sigmaS = makeConstantTexture({2.55f, 3.21f, 3.77f});
    }
    const float eta = r.eta("eta", 1.33f);
    if (in.reflectance) in.table = albedoTable(eta);
    return std::make_shared<Subsurface>(eta, r.roughness(), std::move(in));
}

}  // namespace

bool isPbrt4MaterialName(const std::string& type) {
    return type == "diffuse" || type == "conductor" || type == "dielectric" || type == "thindielectric" ||
           type == "diffusetransmission" || type == "coateddiffuse" || type == "coatedconductor" || type == "subsurface" ||
           type == "hair";
}

std::shared_ptr<Material> makePbrt4Material(const std::string& type, const ParamSet& p, const MaterialContext& c) {
    const Pbrt4Reader r(p, c);
    if (type == "diffuse") return std::make_shared<Diffuse>(r.color("reflectance", grey(0.5f)));
    if (type == "conductor") return std::make_shared<Conductor>(r.conductor(""), r.roughness());
    if (type == "dielectric") return std::make_shared<Dielectric>(r.eta("eta"), r.roughness());
    if (type == "thindielectric") return std::make_shared<ThinDielectricMaterial>(r.eta("eta"));
    if (type == "diffusetransmission")
        return std::make_shared<DiffuseTransmission>(r.color("reflectance", grey(0.25f)), r.color("transmittance", grey(0.25f)),
                                                     float(p.getFloat("scale", 1)));
    if (type == "subsurface") return makeSubsurface(r);
    if (type == "hair") return makeHairMaterial(p, c);
    if (type == "coateddiffuse")
        return std::make_shared<CoatedDiffuseMaterial>(r.color("reflectance", grey(0.5f)), r.roughness(), r.eta("eta"), layerThickness(r));
    return std::make_shared<CoatedConductorMaterial>(r.roughness("interface."), r.eta("interface.eta"), layerThickness(r),
                                                     r.conductor("conductor."), r.roughness("conductor."));
}

}  // namespace lenslab
