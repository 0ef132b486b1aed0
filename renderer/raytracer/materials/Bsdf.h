#pragma once
// A BSDF built the way pbrt-v3 builds one: the lobes a material lays down at a surface hit, each
// with a weight (its colour, times the share a mix material gives it). Lobes work in the local
// shading frame: z along the shading normal as the shape orients it (not turned toward the
// viewer), x along dp/du. Sampling picks a lobe uniformly; f sums the lobes that face the right
// way for the geometric normal; the pdf averages the lobes' densities, so multiple importance
// sampling sees the density that was actually sampled.
#include <array>
#include <cstddef>
#include <new>
#include <type_traits>
#include <utility>

#include "materials/Material.h"

namespace lenslab {

enum LobeType : unsigned { kReflection = 1u, kTransmission = 2u, kSpecular = 4u };

struct LobeSample {
    Vec3f wi;             // local
    Vec3f f;              // BSDF value; for a specular lobe, the delta's weight over |cos(wi)|
    float pdf = 0;        // solid angle; for a specular lobe, the probability of this choice
    bool specular = false;
};

// One lobe, without its weight. f and pdf are zero for specular lobes (deltas are only sampled).
class Lobe {
public:
    virtual unsigned type() const = 0;
    virtual Vec3f f(Vec3f wo, Vec3f wi) const = 0;
    // Cosine-weighted on wo's side, unless the lobe knows better.
    virtual float pdf(Vec3f wo, Vec3f wi) const;
    // uc: a uniform number left over from choosing the lobe, for a lobe's own discrete choice.
    // A non-specular lobe's sample carries f(wo, wi) and pdf(wo, wi) exactly (the Bsdf reuses them).
    virtual bool sample(Vec3f wo, float uc, float u1, float u2, LobeSample& out) const;
    // f and pdf together, for a lobe whose two share most of their work.
    virtual void evaluate(Vec3f wo, Vec3f wi, Vec3f& f, float& pdf) const;

protected:
    ~Lobe() = default;  // lobes live in a Bsdf's storage and are never deleted through a pointer
};

// Local-frame geometry shared by the lobes.
inline bool sameHemisphere(Vec3f a, Vec3f b) { return a.z * b.z > 0; }
inline Vec3f reflect(Vec3f wo, Vec3f n) { return 2.0f * dot(wo, n) * n - wo; }
// Refraction of wo through a surface with normal n on wo's side; eta = index on wo's side over
// the index on the far side. False under total internal reflection.
bool refract(Vec3f wo, Vec3f n, float eta, Vec3f& wt);

class Bsdf {
public:
    static constexpr int kMaxLobes = 16;

    explicit Bsdf(const SurfaceHit& hit);
    // The lobes `material` lays down at `hit`, weight 1: built once per path vertex, for the light
    // sample's evaluation and the BSDF sample both (the textures and the lobes' set-up are not
    // computed again for each).
    Bsdf(const SurfaceHit& hit, const Material& material);
    Bsdf(const Bsdf&) = delete;
    Bsdf& operator=(const Bsdf&) = delete;

    // Adds a lobe L(args...) with `weight`; a black weight adds nothing (as pbrt-v3 skips black
    // lobes). Materials declare their lobe count (Material::maxLobes) so mixes are checked to fit.
    template <class L, class... Args>
    void add(Vec3f weight, Args&&... args) {
        static_assert(std::is_base_of_v<Lobe, L> && std::is_trivially_destructible_v<L>);
        static_assert(sizeof(L) <= sizeof(Slot) && alignof(L) <= alignof(Slot));
        if (isBlack(weight) || count_ == kMaxLobes) return;
        lobes_[count_] = new (slots_[count_].bytes) L(std::forward<Args>(args)...);
        weights_[count_++] = weight;
    }
    // World directions. f(wo, wi) |cos(wi, ns)| without the specular lobes, and in `pdf` the
    // mixture density sample() draws wi with: what a light sample weighed by MIS needs, in one
    // pass over the lobes.
    Vec3f evaluate(Vec3f wo, Vec3f wi, float& pdf) const;
    bool sample(Vec3f wo, float uLobe, float u1, float u2, BsdfSample& out) const;

private:
    Vec3f toLocal(Vec3f w) const { return frame_.toLocal(w); }
    unsigned scatteringType(Vec3f wo, Vec3f wi) const;
    Vec3f toWorld(Vec3f w) const { return frame_.toWorld(w); }

    struct alignas(16) Slot {
        std::byte bytes[128];
    };
    Frame frame_;
    Vec3f ng_;
    int count_ = 0;
    std::array<const Lobe*, kMaxLobes> lobes_{};
    std::array<Vec3f, kMaxLobes> weights_;
    std::array<Slot, kMaxLobes> slots_;
};

}  // namespace lenslab
