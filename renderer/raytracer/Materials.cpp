#include <cmath>

#include "Material.h"
#include "Sampling.h"

namespace lenslab {

namespace {

constexpr float kInvPi = 0.318309886f;

// The shading normal turned toward wo's side of the surface.
Vec3f facing(const SurfaceHit& h, Vec3f wo) { return dot(wo, h.ng) >= 0 ? h.ns : -h.ns; }
bool sameSide(const SurfaceHit& h, Vec3f a, Vec3f b) { return dot(a, h.ng) * dot(b, h.ng) > 0; }
Vec3f reflect(Vec3f wo, Vec3f n) { return 2.0f * dot(wo, n) * n - wo; }

// Unpolarised Fresnel reflectance between dielectrics; cosI > 0 on the etaI side.
float fresnelDielectric(float cosI, float etaI, float etaT) {
    const float sinT = etaI / etaT * std::sqrt(std::max(0.0f, 1.0f - cosI * cosI));
    if (sinT >= 1.0f) return 1.0f;
    const float cosT = std::sqrt(std::max(0.0f, 1.0f - sinT * sinT));
    const float par = (etaT * cosI - etaI * cosT) / (etaT * cosI + etaI * cosT);
    const float perp = (etaI * cosI - etaT * cosT) / (etaI * cosI + etaT * cosT);
    return 0.5f * (par * par + perp * perp);
}

class Matte : public Material {
public:
    explicit Matte(std::shared_ptr<const Texture> kd) : kd_(std::move(kd)) {}
    Vec3f evaluate(const SurfaceHit& h, Vec3f wo, Vec3f wi) const override {
        if (!sameSide(h, wo, wi)) return {};
        return kInvPi * std::fabs(dot(wi, h.ns)) * kd_->evaluate(h);
    }
    float pdf(const SurfaceHit& h, Vec3f wo, Vec3f wi) const override {
        return sameSide(h, wo, wi) ? std::fabs(dot(wi, h.ns)) * kInvPi : 0.0f;
    }
    bool sample(const SurfaceHit& h, Vec3f wo, float, float u1, float u2, BsdfSample& s) const override {
        const Vec3f n = facing(h, wo);
        s.wi = Frame(n).toWorld(cosineHemisphere(u1, u2));
        s.pdf = pdf(h, wo, s.wi);
        if (!(s.pdf > 0)) return false;
        s.weight = kd_->evaluate(h);
        s.specular = false;
        return true;
    }

private:
    std::shared_ptr<const Texture> kd_;
};

// Diffuse base under a rough dielectric coat (Trowbridge-Reitz microfacets, Fresnel at n = 1.5).
class Plastic : public Material {
public:
    Plastic(std::shared_ptr<const Texture> kd, std::shared_ptr<const Texture> ks, float alpha)
        : kd_(std::move(kd)), ks_(std::move(ks)), alpha_(std::max(alpha, 1e-3f)) {}

    Vec3f evaluate(const SurfaceHit& h, Vec3f wo, Vec3f wi) const override {
        if (!sameSide(h, wo, wi)) return {};
        const Frame f(facing(h, wo));
        const Vec3f lo = f.toLocal(wo), li = f.toLocal(wi);
        if (lo.z <= 0 || li.z <= 0) return {};
        const Vec3f m = normalize(lo + li);
        const float spec = D(m) * G(lo, li) * fresnelDielectric(dot(li, m), 1.0f, 1.5f) / (4.0f * lo.z);
        return kInvPi * li.z * kd_->evaluate(h) + spec * ks_->evaluate(h);
    }
    float pdf(const SurfaceHit& h, Vec3f wo, Vec3f wi) const override {
        if (!sameSide(h, wo, wi)) return 0;
        const Frame f(facing(h, wo));
        const Vec3f lo = f.toLocal(wo), li = f.toLocal(wi);
        if (lo.z <= 0 || li.z <= 0) return 0;
        const Vec3f m = normalize(lo + li);
        return 0.5f * li.z * kInvPi + 0.5f * D(m) * m.z / (4.0f * dot(lo, m));
    }
    bool sample(const SurfaceHit& h, Vec3f wo, float uLobe, float u1, float u2, BsdfSample& s) const override {
        const Frame f(facing(h, wo));
        const Vec3f lo = f.toLocal(wo);
        if (lo.z <= 0) return false;
        Vec3f li;
        if (uLobe < 0.5f) {
            li = cosineHemisphere(u1, u2);
        } else {
            const float tan2 = alpha_ * alpha_ * u1 / std::max(1.0f - u1, 1e-7f);
            const float cosT = 1.0f / std::sqrt(1.0f + tan2), sinT = std::sqrt(std::max(0.0f, 1.0f - cosT * cosT));
            const float phi = 2.0f * float(M_PI) * u2;
            const Vec3f m{sinT * std::cos(phi), sinT * std::sin(phi), cosT};
            li = reflect(lo, m);
        }
        if (li.z <= 0) return false;
        s.wi = f.toWorld(li);
        s.pdf = pdf(h, wo, s.wi);
        if (!(s.pdf > 0)) return false;
        s.weight = evaluate(h, wo, s.wi) / s.pdf;
        s.specular = false;
        return allFinite(s.weight);
    }

private:
    float D(Vec3f m) const {
        if (m.z <= 0) return 0;
        const float c2 = m.z * m.z, tan2 = (1 - c2) / c2, a2 = alpha_ * alpha_;
        const float e = 1 + tan2 / a2;
        return 1.0f / (float(M_PI) * a2 * c2 * c2 * e * e);
    }
    float lambda(Vec3f w) const {
        const float c2 = w.z * w.z, tan2 = std::max(0.0f, 1 - c2) / c2;
        return 0.5f * (-1.0f + std::sqrt(1.0f + alpha_ * alpha_ * tan2));
    }
    float G(Vec3f a, Vec3f b) const { return 1.0f / (1.0f + lambda(a) + lambda(b)); }

    std::shared_ptr<const Texture> kd_, ks_;
    float alpha_;
};

class Mirror : public Material {
public:
    explicit Mirror(std::shared_ptr<const Texture> kr) : kr_(std::move(kr)) {}
    Vec3f evaluate(const SurfaceHit&, Vec3f, Vec3f) const override { return {}; }
    float pdf(const SurfaceHit&, Vec3f, Vec3f) const override { return 0; }
    bool sample(const SurfaceHit& h, Vec3f wo, float, float, float, BsdfSample& s) const override {
        s.wi = reflect(wo, facing(h, wo));
        s.weight = kr_->evaluate(h);
        s.pdf = 1;
        s.specular = true;
        return sameSide(h, wo, s.wi);
    }
    bool isSpecular() const override { return true; }

private:
    std::shared_ptr<const Texture> kr_;
};

// Smooth dielectric: Fresnel-weighted choice of reflection or refraction.
class Glass : public Material {
public:
    Glass(std::shared_ptr<const Texture> kr, std::shared_ptr<const Texture> kt, float eta)
        : kr_(std::move(kr)), kt_(std::move(kt)), eta_(eta) {}
    Vec3f evaluate(const SurfaceHit&, Vec3f, Vec3f) const override { return {}; }
    float pdf(const SurfaceHit&, Vec3f, Vec3f) const override { return 0; }
    bool sample(const SurfaceHit& h, Vec3f wo, float uLobe, float, float, BsdfSample& s) const override {
        const bool entering = dot(wo, h.ng) > 0;
        const Vec3f n = entering ? h.ns : -h.ns;
        const float etaI = entering ? 1.0f : eta_, etaT = entering ? eta_ : 1.0f;
        const float cosI = std::max(0.0f, dot(wo, n));
        const float F = fresnelDielectric(cosI, etaI, etaT);
        s.pdf = 1;
        s.specular = true;
        if (uLobe < F) {
            s.wi = reflect(wo, n);
            s.weight = kr_->evaluate(h);
            return true;
        }
        const float ratio = etaI / etaT;
        const float sin2T = ratio * ratio * std::max(0.0f, 1.0f - cosI * cosI);
        if (sin2T >= 1.0f) return false;
        const float cosT = std::sqrt(1.0f - sin2T);
        s.wi = normalize(-ratio * wo + (ratio * cosI - cosT) * n);
        s.weight = ratio * ratio * kt_->evaluate(h);  // radiance is compressed entering denser glass
        return true;
    }
    bool isSpecular() const override { return true; }

private:
    std::shared_ptr<const Texture> kr_, kt_;
    float eta_;
};

// pbrt-v3's map from a perceptual roughness in [0, 1] to the Trowbridge-Reitz alpha.
float roughnessToAlpha(float roughness) {
    const float x = std::log(std::max(roughness, 1e-3f));
    return 1.62142f + 0.819955f * x + 0.1734f * x * x + 0.0171201f * x * x * x + 0.000640711f * x * x * x * x;
}

float constantFloat(const ParamSet& p, const std::string& name, float fallback) {
    if (p.has(name) && p.getColorOrTexture(name, {}).texture)
        p.fail("parameter \"" + name + "\" must be a number here (float textures are not supported)");
    return float(p.getFloat(name, fallback));
}

}  // namespace

std::shared_ptr<const Material> makeDefaultMaterial() {
    return std::make_shared<Matte>(makeConstantTexture({0.5f, 0.5f, 0.5f}));
}

std::shared_ptr<const Material> makeMaterial(const std::string& type, const ParamSet& p, const TextureMap& textures,
                                             std::vector<std::string>& warnings) {
    std::shared_ptr<const Material> m;
    if (type == "matte") {
        if (constantFloat(p, "sigma", 0) != 0)
            p.fail("matte \"sigma\" (Oren-Nayar roughness) is not supported; use sigma 0");
        m = std::make_shared<Matte>(textureParam(p, "Kd", {0.5f, 0.5f, 0.5f}, textures));
    } else if (type == "plastic") {
        const float roughness = constantFloat(p, "roughness", 0.1f);
        const float alpha = p.getBool("remaproughness", true) ? roughnessToAlpha(roughness) : roughness;
        m = std::make_shared<Plastic>(textureParam(p, "Kd", {0.25f, 0.25f, 0.25f}, textures),
                                      textureParam(p, "Ks", {0.25f, 0.25f, 0.25f}, textures), alpha);
    } else if (type == "mirror") {
        m = std::make_shared<Mirror>(textureParam(p, "Kr", {0.9f, 0.9f, 0.9f}, textures));
    } else if (type == "glass") {
        const float eta = constantFloat(p, "eta", constantFloat(p, "index", 1.5f));
        if (!(eta > 0)) p.fail("glass \"eta\" must be positive");
        if (p.has("uroughness") || p.has("vroughness")) {
            if (constantFloat(p, "uroughness", 0) != 0 || constantFloat(p, "vroughness", 0) != 0)
                p.fail("rough glass is not supported; uroughness and vroughness must be 0");
        }
        m = std::make_shared<Glass>(textureParam(p, "Kr", {1, 1, 1}, textures),
                                    textureParam(p, "Kt", {1, 1, 1}, textures), eta);
    } else if (type == "" || type == "none") {
        p.fail("material type \"" + type + "\" is not supported (matte, plastic, mirror, glass)");
    } else {
        p.fail("material \"" + type + "\" is not supported (matte, plastic, mirror, glass)");
    }
    p.checkAllUsed(warnings, {"remaproughness"});
    return m;
}

}  // namespace lenslab
