#include "materials/Bsdf.h"

#include <cmath>

#include "core/Pi.h"
#include "sampling/Sampling.h"

namespace lenslab {

namespace {

// pbrt-v3's shading frame: the shading normal with dp/du made orthogonal to it; any frame around
// the normal when the shape gives no usable dp/du (only anisotropic lobes can tell the difference).
Frame shadingFrame(const SurfaceHit& h) {
    Frame f(h.ns);
    const Vec3f t = h.dpdu - dot(h.dpdu, h.ns) * h.ns;
    const float len = length(t);
    if (len > 1e-6f * length(h.dpdu) && len > 0) {
        f.s = t / len;
        f.t = cross(h.ns, f.s);
    }
    return f;
}

}  // namespace

float Lobe::pdf(Vec3f wo, Vec3f wi) const { return sameHemisphere(wo, wi) ? std::fabs(wi.z) * kInvPif : 0.0f; }

bool Lobe::sample(Vec3f wo, float, float u1, float u2, LobeSample& s) const {
    s.wi = cosineHemisphere(u1, u2);
    if (wo.z < 0) s.wi.z = -s.wi.z;
    s.pdf = pdf(wo, s.wi);
    s.f = f(wo, s.wi);
    s.specular = false;
    return s.pdf > 0;
}

void Lobe::evaluate(Vec3f wo, Vec3f wi, Vec3f& value, float& density) const {
    value = f(wo, wi);
    density = pdf(wo, wi);
}

bool refract(Vec3f wo, Vec3f n, float eta, Vec3f& wt) {
    const float cosI = dot(wo, n);
    const float sin2T = eta * eta * std::max(0.0f, 1.0f - cosI * cosI);
    if (sin2T >= 1.0f) return false;
    const float cosT = std::sqrt(1.0f - sin2T);
    wt = -eta * wo + (eta * cosI - cosT) * n;
    return true;
}

Bsdf::Bsdf(const SurfaceHit& hit) : frame_(shadingFrame(hit)), ng_(hit.ng) {}

Bsdf::Bsdf(const SurfaceHit& hit, const Material& material) : Bsdf(hit) { material.addLobes(hit, {1, 1, 1}, *this); }

// The geometric normal decides reflection or transmission, so that interpolated shading normals
// cannot leak light through a surface: the lobe types that count for this pair of directions.
unsigned Bsdf::scatteringType(Vec3f woWorld, Vec3f wiWorld) const {
    return dot(wiWorld, ng_) * dot(woWorld, ng_) > 0 ? kReflection : kTransmission;
}

Vec3f Bsdf::evaluate(Vec3f woWorld, Vec3f wiWorld, float& pdf) const {
    pdf = 0;
    if (count_ == 0) return {};
    const Vec3f wo = toLocal(woWorld), wi = toLocal(wiWorld);
    if (wo.z == 0) return {};
    const unsigned wanted = scatteringType(woWorld, wiWorld);
    Vec3f sum{};
    float pdfSum = 0;
    for (int i = 0; i < count_; ++i) {
        const unsigned t = lobes_[i]->type();
        if (t & kSpecular) continue;
        if (t & wanted) {
            Vec3f f;
            float p;
            lobes_[i]->evaluate(wo, wi, f, p);
            sum += weights_[i] * f;
            pdfSum += p;
        } else {
            pdfSum += lobes_[i]->pdf(wo, wi);
        }
    }
    pdf = pdfSum / float(count_);
    return sum * std::fabs(wi.z);
}

bool Bsdf::sample(Vec3f woWorld, float uLobe, float u1, float u2, BsdfSample& out) const {
    if (count_ == 0) return false;
    const Vec3f wo = toLocal(woWorld);
    if (wo.z == 0) return false;
    const int chosen = std::min(int(uLobe * float(count_)), count_ - 1);
    const float uc = std::min(uLobe * float(count_) - float(chosen), 0x1.fffffep-1f);
    LobeSample ls;
    if (!lobes_[chosen]->sample(wo, uc, u1, u2, ls) || !(ls.pdf > 0) || ls.wi.z == 0) return false;
    out.wi = toWorld(ls.wi);
    out.specular = ls.specular;
    if (ls.specular) {
        // A delta lobe: the direction must leave on the side the lobe scatters to.
        const bool reflection = dot(out.wi, ng_) * dot(woWorld, ng_) > 0;
        if (reflection != sameHemisphere(wo, ls.wi)) return false;
        out.pdf = ls.pdf / float(count_);
        out.weight = weights_[chosen] * ls.f * (std::fabs(ls.wi.z) / out.pdf);
    } else {
        // The mixture's f and pdf at wi, the chosen lobe's own terms taken from its sample.
        const unsigned wanted = scatteringType(woWorld, out.wi);
        Vec3f f{};
        float pdfSum = 0;
        for (int i = 0; i < count_; ++i) {
            const unsigned t = lobes_[i]->type();
            if (t & kSpecular) continue;
            pdfSum += i == chosen ? ls.pdf : lobes_[i]->pdf(wo, ls.wi);
            if (t & wanted) f += weights_[i] * (i == chosen ? ls.f : lobes_[i]->f(wo, ls.wi));
        }
        out.pdf = pdfSum / float(count_);
        out.weight = f * (std::fabs(ls.wi.z) / out.pdf);
    }
    return out.pdf > 0 && allFinite(out.weight);
}

// The Material interface, answered by the Bsdf the material lays down at the hit.

Vec3f Material::evaluate(const SurfaceHit& hit, Vec3f wo, Vec3f wi) const {
    float pdf;
    return Bsdf(hit, *this).evaluate(wo, wi, pdf);
}

float Material::pdf(const SurfaceHit& hit, Vec3f wo, Vec3f wi) const {
    float pdf;
    Bsdf(hit, *this).evaluate(wo, wi, pdf);
    return pdf;
}

bool Material::sample(const SurfaceHit& hit, Vec3f wo, float uLobe, float u1, float u2, BsdfSample& out) const {
    return Bsdf(hit, *this).sample(wo, uLobe, u1, u2, out);
}

}  // namespace lenslab
