// pbrt-v3's materials: what lobes each lays down at a hit, from its (possibly textured)
// parameters, with pbrt-v3's names and defaults.
#include <cmath>

#include "materials/Bsdf.h"
#include "materials/DiffuseLobes.h"
#include "materials/MeasuredBrdf.h"
#include "materials/MetalSpectra.h"
#include "materials/MicrofacetLobes.h"
#include "materials/Pbrt4Materials.h"
#include "materials/SpecularLobes.h"

namespace lenslab {

namespace {

// A float parameter that may name a float texture; its value is the texture's first channel.
float floatAt(const TexturePtr& t, const SurfaceHit& h) { return t->evaluate(h).x; }

// An index of refraction from a texture, which may hold anything: 1 (no boundary) unless positive.
float indexAt(const TexturePtr& t, const SurfaceHit& h) {
    const float eta = floatAt(t, h);
    return eta > 0 ? eta : 1.0f;
}

// Microfacet widths from pbrt-v3's roughness parameters (per hit, as they may be textures).
struct Pbrt3Roughness {
    TexturePtr u, v;
    bool remap = true;
    MicrofacetKind kind = MicrofacetKind::TrowbridgeReitz;

    // pbrt-v3 tests for a smooth surface before remapping: 0 means specular, remapped or not.
    bool smoothAt(const SurfaceHit& h) const { return floatAt(u, h) == 0 && floatAt(v, h) == 0; }
    MicrofacetDistribution at(const SurfaceHit& h) const {
        float au = floatAt(u, h), av = floatAt(v, h);
        if (remap) {
            au = roughnessToAlpha(au);
            av = roughnessToAlpha(av);
        }
        return {kind, au, av};
    }
};

class Matte final : public Material {
public:
    Matte(TexturePtr kd, TexturePtr sigma) : kd_(std::move(kd)), sigma_(std::move(sigma)) {}
    void addLobes(const SurfaceHit& h, Vec3f scale, Bsdf& b) const override {
        const Vec3f w = scale * atLeastZero(kd_->evaluate(h));
        const float sigma = std::clamp(floatAt(sigma_, h), 0.0f, 90.0f);
        if (sigma == 0) b.add<LambertianReflection>(w);
        else b.add<OrenNayar>(w, sigma);
    }
    int maxLobes() const override { return 1; }

private:
    TexturePtr kd_, sigma_;
};

// A diffuse base under a glossy dielectric coat. The coat's Fresnel factor takes pbrt-v3's
// indices as they are, 1.5 on the incident side and 1 beyond (pbrt-v3 issue #210, kept there so
// that existing scenes render unchanged): past about 42 degrees from the facet normal the coat
// reflects totally on surfaces whose normals face the viewer.
class Plastic final : public Material {
public:
    Plastic(TexturePtr kd, TexturePtr ks, Pbrt3Roughness r) : kd_(std::move(kd)), ks_(std::move(ks)), rough_(std::move(r)) {}
    void addLobes(const SurfaceHit& h, Vec3f scale, Bsdf& b) const override {
        b.add<LambertianReflection>(scale * atLeastZero(kd_->evaluate(h)));
        const Vec3f ks = scale * atLeastZero(ks_->evaluate(h));
        if (!isBlack(ks)) b.add<MicrofacetReflection>(ks, rough_.at(h), Fresnel::dielectric(1.5f, 1.0f));
    }
    int maxLobes() const override { return 2; }

private:
    TexturePtr kd_, ks_;
    Pbrt3Roughness rough_;
};

class Metal final : public Material {
public:
    Metal(TexturePtr eta, TexturePtr k, Pbrt3Roughness r) : eta_(std::move(eta)), k_(std::move(k)), rough_(std::move(r)) {}
    void addLobes(const SurfaceHit& h, Vec3f scale, Bsdf& b) const override {
        b.add<MicrofacetReflection>(scale, rough_.at(h), Fresnel::conductor(eta_->evaluate(h), k_->evaluate(h)));
    }
    int maxLobes() const override { return 1; }

private:
    TexturePtr eta_, k_;
    Pbrt3Roughness rough_;
};

class Mirror final : public Material {
public:
    explicit Mirror(TexturePtr kr) : kr_(std::move(kr)) {}
    void addLobes(const SurfaceHit& h, Vec3f scale, Bsdf& b) const override {
        b.add<SpecularReflection>(scale * atLeastZero(kr_->evaluate(h)), Fresnel::one());
    }
    int maxLobes() const override { return 1; }
    bool isSpecular() const override { return true; }

private:
    TexturePtr kr_;
};

// A dielectric boundary from air (the normal's side) into index eta: smooth (one lobe choosing
// reflection or refraction by Fresnel) or rough (microfacet reflection and transmission).
class Glass final : public Material {
public:
    Glass(TexturePtr kr, TexturePtr kt, TexturePtr eta, Pbrt3Roughness r, bool alwaysSmooth)
        : kr_(std::move(kr)), kt_(std::move(kt)), eta_(std::move(eta)), rough_(std::move(r)), alwaysSmooth_(alwaysSmooth) {}
    void addLobes(const SurfaceHit& h, Vec3f scale, Bsdf& b) const override {
        const Vec3f r = atLeastZero(kr_->evaluate(h)), t = atLeastZero(kt_->evaluate(h));
        if (isBlack(r) && isBlack(t)) return;
        const float eta = indexAt(eta_, h);
        if (rough_.smoothAt(h)) {
            b.add<FresnelSpecular>(scale, r, t, 1.0f, eta);
            return;
        }
        const MicrofacetDistribution d = rough_.at(h);
        b.add<MicrofacetReflection>(scale * r, d, Fresnel::dielectric(1.0f, eta));
        b.add<MicrofacetTransmission>(scale * t, d, 1.0f, eta);
    }
    int maxLobes() const override { return 2; }
    bool isSpecular() const override { return alwaysSmooth_; }

private:
    TexturePtr kr_, kt_, eta_;
    Pbrt3Roughness rough_;
    bool alwaysSmooth_;
};

class Substrate final : public Material {
public:
    Substrate(TexturePtr kd, TexturePtr ks, Pbrt3Roughness r) : kd_(std::move(kd)), ks_(std::move(ks)), rough_(std::move(r)) {}
    void addLobes(const SurfaceHit& h, Vec3f scale, Bsdf& b) const override {
        const Vec3f kd = atLeastZero(kd_->evaluate(h)), ks = atLeastZero(ks_->evaluate(h));
        if (isBlack(kd) && isBlack(ks)) return;
        b.add<FresnelBlend>(scale, kd, ks, rough_.at(h));
    }
    int maxLobes() const override { return 1; }

private:
    TexturePtr kd_, ks_;
    Pbrt3Roughness rough_;
};

// pbrt-v3's catch-all: diffuse, glossy coat, mirror reflection and refraction (no bending at the
// far side: a thin sheet is two surfaces), all scaled by opacity; the rest passes straight through.
class Uber final : public Material {
public:
    struct Inputs {
        TexturePtr kd, ks, kr, kt, opacity, eta;
        Pbrt3Roughness rough;
    };
    explicit Uber(Inputs in) : in_(std::move(in)) {}
    void addLobes(const SurfaceHit& h, Vec3f scale, Bsdf& b) const override {
        const Vec3f op = atLeastZero(in_.opacity->evaluate(h));
        b.add<SpecularTransmission>(scale * atLeastZero(Vec3f{1, 1, 1} - op), 1.0f, 1.0f);
        const float eta = indexAt(in_.eta, h);
        const Vec3f w = scale * op;
        b.add<LambertianReflection>(w * atLeastZero(in_.kd->evaluate(h)));
        const Vec3f ks = w * atLeastZero(in_.ks->evaluate(h));
        if (!isBlack(ks)) b.add<MicrofacetReflection>(ks, in_.rough.at(h), Fresnel::dielectric(1.0f, eta));
        b.add<SpecularReflection>(w * atLeastZero(in_.kr->evaluate(h)), Fresnel::dielectric(1.0f, eta));
        b.add<SpecularTransmission>(w * atLeastZero(in_.kt->evaluate(h)), 1.0f, eta);
    }
    int maxLobes() const override { return 5; }

private:
    Inputs in_;
};

// Diffuse and glossy reflection and transmission through a thin sheet (index 1.5), split by the
// "reflect" and "transmit" colours.
class Translucent final : public Material {
public:
    struct Inputs {
        TexturePtr kd, ks, reflect, transmit;
        Pbrt3Roughness rough;
    };
    explicit Translucent(Inputs in) : in_(std::move(in)) {}
    void addLobes(const SurfaceHit& h, Vec3f scale, Bsdf& b) const override {
        constexpr float kEta = 1.5f;
        const Vec3f r = atLeastZero(in_.reflect->evaluate(h)), t = atLeastZero(in_.transmit->evaluate(h));
        if (isBlack(r) && isBlack(t)) return;
        const Vec3f kd = scale * atLeastZero(in_.kd->evaluate(h));
        b.add<LambertianReflection>(r * kd);
        b.add<LambertianTransmission>(t * kd);
        const Vec3f ks = scale * atLeastZero(in_.ks->evaluate(h));
        if (isBlack(ks)) return;
        const MicrofacetDistribution d = in_.rough.at(h);
        b.add<MicrofacetReflection>(r * ks, d, Fresnel::dielectric(1.0f, kEta));
        b.add<MicrofacetTransmission>(t * ks, d, 1.0f, kEta);
    }
    int maxLobes() const override { return 4; }

private:
    Inputs in_;
};

// pbrt-v3's mix: the first material's lobes scaled by "amount", the second's by 1 - amount.
class Mix final : public Material {
public:
    Mix(std::shared_ptr<const Material> a, std::shared_ptr<const Material> b, TexturePtr amount)
        : a_(std::move(a)), b_(std::move(b)), amount_(std::move(amount)) {}
    void addLobes(const SurfaceHit& h, Vec3f scale, Bsdf& b) const override {
        const Vec3f s = atLeastZero(amount_->evaluate(h));
        a_->addLobes(h, scale * s, b);
        b_->addLobes(h, scale * atLeastZero(Vec3f{1, 1, 1} - s), b);
    }
    int maxLobes() const override { return a_->maxLobes() + b_->maxLobes(); }
    bool isSpecular() const override { return a_->isSpecular() && b_->isSpecular(); }

private:
    std::shared_ptr<const Material> a_, b_;
    TexturePtr amount_;
};

class Measured final : public Material {
public:
    explicit Measured(std::shared_ptr<const MeasuredBrdf> brdf) : brdf_(std::move(brdf)) {}
    void addLobes(const SurfaceHit&, Vec3f scale, Bsdf& b) const override { b.add<MeasuredLobe>(scale, brdf_.get()); }
    int maxLobes() const override { return 1; }

private:
    std::shared_ptr<const MeasuredBrdf> brdf_;
};

// No surface at all (pbrt's "none" / "interface", which bound participating media): rays carry
// on unchanged. The path integrator sees a specular transmission with weight 1 and no bending.
class Passthrough final : public Material {
public:
    void addLobes(const SurfaceHit&, Vec3f scale, Bsdf& b) const override { b.add<SpecularTransmission>(scale, 1.0f, 1.0f); }
    int maxLobes() const override { return 1; }
    bool isSpecular() const override { return true; }
    bool isPassthrough() const override { return true; }
};

// --- reading the parameters ----------------------------------------------------------------------

class Pbrt3Reader {
public:
    Pbrt3Reader(const ParamSet& p, const MaterialContext& c) : p_(p), c_(c) {}

    TexturePtr color(const std::string& name, Vec3f fallback) const { return textureParam(p_, name, fallback, c_.textures); }
    TexturePtr number(const std::string& name, float fallback) const { return floatTextureParam(p_, name, fallback, c_.textures); }
    // A float parameter that, when absent, takes another parameter's value.
    TexturePtr numberOr(const std::string& name, const TexturePtr& fallback) const {
        return p_.has(name) ? number(name, 0) : fallback;
    }
    [[noreturn]] void fail(const std::string& message) const { p_.fail(message); }
    void warn(const std::string& message) const { c_.warnings.push_back(describe(p_.where()) + ": " + message); }
    // A number given in the scene (no texture) equal to `value`, or absent with that default.
    bool isConstant(const std::string& name, float fallback, float value) const {
        const ColorOrTexture c = p_.getColorOrTexture(name, grey(fallback));
        return !c.texture && c.color.x == value;
    }
    // pbrt-v3's "eta", or its older name "index"; default 1.5.
    TexturePtr refractiveIndex() const {
        const std::string name = p_.has("eta") ? "eta" : "index";
        const ColorOrTexture c = p_.getColorOrTexture(name, grey(1.5f));
        if (!c.texture && !(c.color.x > 0)) p_.fail("\"" + name + "\" (index of refraction) must be positive");
        return number(name, 1.5f);
    }
    // pbrt-v3's "remaproughness" and lenslab's "distribution" (trowbridgereitz or beckmann).
    Pbrt3Roughness roughness(TexturePtr u, TexturePtr v) const {
        Pbrt3Roughness r{std::move(u), std::move(v), p_.getBool("remaproughness", true), MicrofacetKind::TrowbridgeReitz};
        const std::string kind = p_.getString("distribution", "trowbridgereitz");
        if (kind == "beckmann") r.kind = MicrofacetKind::Beckmann;
        else if (kind != "trowbridgereitz" && kind != "ggx")
            p_.fail("\"distribution\" must be trowbridgereitz (ggx) or beckmann, not \"" + kind + "\"");
        return r;
    }
    Pbrt3Roughness isotropicRoughness(float fallback) const {
        const TexturePtr r = number("roughness", fallback);
        return roughness(r, r);
    }
    std::shared_ptr<const Material> named(const std::string& param) const {
        const std::string n = p_.getString(param, "");
        if (n.empty()) p_.fail("mix needs \"string " + param + "\" naming a material");
        const auto it = c_.named.find(n);
        if (it == c_.named.end()) p_.fail("\"" + param + "\" names an undefined material \"" + n + "\"");
        return it->second;
    }

private:
    const ParamSet& p_;
    const MaterialContext& c_;
};

std::shared_ptr<Material> makeMetal(const Pbrt3Reader& r) {
    // pbrt-v3's default is copper.
    static const Vec3f copperEta = namedSpectrumRgb("metal-Cu-eta").value(), copperK = namedSpectrumRgb("metal-Cu-k").value();
    const TexturePtr rough = r.number("roughness", 0.01f);
    const TexturePtr u = r.numberOr("uroughness", rough), v = r.numberOr("vroughness", rough);
    return std::make_shared<Metal>(r.color("eta", copperEta), r.color("k", copperK), r.roughness(u, v));
}

std::shared_ptr<Material> makeGlass(const Pbrt3Reader& r) {
    const bool smooth = r.isConstant("uroughness", 0, 0) && r.isConstant("vroughness", 0, 0);
    return std::make_shared<Glass>(r.color("Kr", {1, 1, 1}), r.color("Kt", {1, 1, 1}), r.refractiveIndex(),
                                   r.roughness(r.number("uroughness", 0), r.number("vroughness", 0)), smooth);
}

std::shared_ptr<Material> makeUber(const Pbrt3Reader& r) {
    const TexturePtr u = r.numberOr("uroughness", r.number("roughness", 0.1f));
    const TexturePtr v = r.numberOr("vroughness", u);  // pbrt-v3: v follows u, not "roughness"
    return std::make_shared<Uber>(Uber::Inputs{r.color("Kd", grey(0.25f)), r.color("Ks", grey(0.25f)),
                                               r.color("Kr", grey(0)), r.color("Kt", grey(0)),
                                               r.color("opacity", grey(1)),
                                               r.refractiveIndex(),
                                               r.roughness(u, v)});
}

std::shared_ptr<Material> makeMix(const Pbrt3Reader& r, const ParamSet& p, const MaterialContext& c) {
    // pbrt-v4 names both in "materials" and picks the second with probability "amount": the
    // average is pbrt-v3's mix with the two swapped.
    const bool v4 = p.has("materials");
    std::shared_ptr<const Material> a, b;
    if (v4) {
        const std::vector<std::string> names = p.getStrings("materials");
        if (names.size() != 2) p.fail("mix needs two names in \"materials\"");
        for (int i = 0; i < 2; ++i) {
            const auto it = c.named.find(names[i]);
            if (it == c.named.end()) p.fail("\"materials\" names an undefined material \"" + names[i] + "\"");
            (i == 0 ? b : a) = it->second;
        }
    } else {
        a = r.named("namedmaterial1");
        b = r.named("namedmaterial2");
    }
    if (a->hasInterior() || b->hasInterior())
        r.fail("a subsurface material cannot be mixed: its scattering volume belongs to one surface");
    if (a->maxLobes() + b->maxLobes() > Bsdf::kMaxLobes)
        r.fail("mix of materials with more than " + std::to_string(Bsdf::kMaxLobes) + " lobes in all");
    // One hit has one shading frame, the mix's own, which has no bump map (as in pbrt-v3).
    if (a->hasBumpMap() || b->hasBumpMap())
        r.warn("the bump maps of the materials inside a mix are not applied");
    return std::make_shared<Mix>(std::move(a), std::move(b), v4 ? r.number("amount", 0.5f) : r.color("amount", grey(0.5f)));
}

// pbrt-v3 reads a bump map for every material but mix and none (which has no surface to bump).
bool takesBumpMap(const std::string& type) { return type != "mix" && type != "" && type != "none" && type != "interface"; }

const char* kSupported =
    "(matte, plastic, metal, mirror, glass, substrate, uber, translucent, mix, measured, none, interface; pbrt-v4's "
    "diffuse, conductor, dielectric, thindielectric, diffusetransmission, coateddiffuse, coatedconductor, subsurface, hair)";

}  // namespace

std::shared_ptr<const Material> makeDefaultMaterial() {
    return std::make_shared<Matte>(makeConstantTexture(grey(0.5f)), makeConstantTexture(grey(0)));
}

std::shared_ptr<const Material> makeMaterial(const std::string& type, const ParamSet& p, const MaterialContext& c) {
    const Pbrt3Reader r(p, c);
    std::shared_ptr<Material> m;
    if (type == "matte") {
        m = std::make_shared<Matte>(r.color("Kd", grey(0.5f)), r.number("sigma", 0));
    } else if (type == "plastic") {
        m = std::make_shared<Plastic>(r.color("Kd", grey(0.25f)), r.color("Ks", grey(0.25f)), r.isotropicRoughness(0.1f));
    } else if (type == "metal") {
        m = makeMetal(r);
    } else if (type == "mirror") {
        m = std::make_shared<Mirror>(r.color("Kr", grey(0.9f)));
    } else if (type == "glass") {
        m = makeGlass(r);
    } else if (type == "substrate") {
        m = std::make_shared<Substrate>(r.color("Kd", grey(0.5f)), r.color("Ks", grey(0.5f)),
                                        r.roughness(r.number("uroughness", 0.1f), r.number("vroughness", 0.1f)));
    } else if (type == "uber") {
        m = makeUber(r);
    } else if (type == "translucent") {
        m = std::make_shared<Translucent>(Translucent::Inputs{r.color("Kd", grey(0.25f)), r.color("Ks", grey(0.25f)),
                                                              r.color("reflect", grey(0.5f)),
                                                              r.color("transmit", grey(0.5f)),
                                                              r.isotropicRoughness(0.1f)});
    } else if (type == "mix") {
        m = makeMix(r, p, c);
    } else if (type == "measured") {
        const std::string name = p.getString("filename", "");
        if (name.empty()) p.fail("measured needs \"string filename\" (a .brdf or MERL file)");
        m = std::make_shared<Measured>(loadMeasuredBrdf(c.resolve(name, p.where()), name, p));
    } else if (type == "" || type == "none" || type == "interface") {
        m = std::make_shared<Passthrough>();
    } else if (isPbrt4MaterialName(type)) {
        m = makePbrt4Material(type, p, c);
    } else {
        p.fail("material \"" + type + "\" is not supported " + kSupported);
    }
    if (takesBumpMap(type) && p.has("bumpmap")) m->setBumpMap(r.number("bumpmap", 0));
    if (takesBumpMap(type) && p.has("displacement")) m->setBumpMap(r.number("displacement", 0));  // pbrt-v4's name
    p.checkAllUsed(c.warnings, {"remaproughness"});
    return m;
}

}  // namespace lenslab
