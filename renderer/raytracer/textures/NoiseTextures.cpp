// pbrt-v3's textures built on Perlin noise: dots (jittered polka dots over (s, t)), and in the
// texture's 3D space fbm, wrinkled (turbulence), windy (waves under gusts) and marble.
#include <algorithm>
#include <cmath>

#include "sampling/Noise.h"
#include "textures/TextureClasses.h"
#include "textures/TextureMapping.h"

namespace lenslab {

namespace {

float noise2(float x, float y) { return perlinNoise({x, y, 0.5f}); }

// One dot per unit cell of (s, t), present where the noise at the cell is positive, of radius
// 0.35 and shifted by noise up to 0.15 from the cell's centre.
class DotsTexture : public Texture {
public:
    DotsTexture(TextureMapping2D map, std::shared_ptr<const Texture> dot, std::shared_ptr<const Texture> background)
        : map_(std::move(map)), dot_(std::move(dot)), background_(std::move(background)) {}
    Vec3f evaluate(const SurfaceHit& h) const override {
        const TexCoord c = map_.map(h);
        const float sCell = std::floor(c.s + 0.5f), tCell = std::floor(c.t + 0.5f);
        if (noise2(sCell + 0.5f, tCell + 0.5f) > 0) {
            constexpr float radius = 0.35f, maxShift = 0.5f - radius;
            const float ds = c.s - (sCell + maxShift * noise2(sCell + 1.5f, tCell + 2.8f));
            const float dt = c.t - (tCell + maxShift * noise2(sCell + 4.5f, tCell + 9.8f));
            if (ds * ds + dt * dt < radius * radius) return dot_->evaluate(h);
        }
        return background_->evaluate(h);
    }

private:
    TextureMapping2D map_;
    std::shared_ptr<const Texture> dot_, background_;
};

// A float function of the point in texture space, in all three channels.
template <typename F>
class Noise3DTexture : public Texture {
public:
    Noise3DTexture(TextureMapping3D map, F f) : map_(std::move(map)), f_(std::move(f)) {}
    Vec3f evaluate(const SurfaceHit& h) const override {
        const float x = f_(map_.map(h));
        return {x, x, x};
    }

private:
    TextureMapping3D map_;
    F f_;
};

template <typename F>
std::shared_ptr<const Texture> noise3D(const TextureRequest& r, F f) {
    return std::make_shared<Noise3DTexture<F>>(TextureMapping3D(r.textureToWorld), std::move(f));
}

int octavesParam(const ParamSet& p) {
    const int octaves = p.getInt("octaves", 8);
    if (octaves < 0 || octaves > 32) p.fail("\"octaves\" must lie in [0, 32]");
    return octaves;
}

// Veins: a sine of height perturbed by fbm, coloured along a cubic Bezier spline through
// pbrt-v3's nine marble colours.
class MarbleTexture : public Texture {
public:
    MarbleTexture(TextureMapping3D map, int octaves, float omega, float scale, float variation)
        : map_(std::move(map)), octaves_(octaves), omega_(omega), scale_(scale), variation_(variation) {}
    Vec3f evaluate(const SurfaceHit& h) const override {
        static constexpr Vec3f kColours[] = {{.58f, .58f, .6f}, {.58f, .58f, .6f}, {.58f, .58f, .6f},
                                             {.5f, .5f, .5f},   {.6f, .59f, .58f}, {.58f, .58f, .6f},
                                             {.58f, .58f, .6f}, {.2f, .2f, .33f},  {.58f, .58f, .6f}};
        constexpr int kSegments = 9 - 3;
        const Vec3f p = scale_ * map_.map(h);
        const float t = 0.5f + 0.5f * std::sin(p.y + variation_ * fractionalBrownianMotion(p, omega_, octaves_));
        // pbrt-v3 caps the first control point at 1 (min(1, ...)), which extrapolates the spline
        // to albedos near 40; pbrt-v2 and pbrt-v4 cap it at the last segment, as here.
        const int first = std::clamp(int(std::floor(t * kSegments)), 0, kSegments - 1);
        const float u = t * kSegments - float(first);
        const Vec3f* c = &kColours[first];
        const float w = 1 - u;  // Bernstein weights of the cubic Bezier segment
        return 1.5f * (w * w * w * c[0] + 3 * w * w * u * c[1] + 3 * w * u * u * c[2] + u * u * u * c[3]);
    }

private:
    TextureMapping3D map_;
    int octaves_;
    float omega_, scale_, variation_;
};

}  // namespace

// pbrt-v3 hands "inside" to the texture's outside-the-dot slot and "outside" to the dots
// themselves; lenslab keeps that, so scenes look as they do in pbrt-v3.
std::shared_ptr<const Texture> makeDotsTexture(const TextureRequest& r) {
    auto background = r.operand("inside", 1);
    auto dot = r.operand("outside", 0);
    return std::make_shared<DotsTexture>(TextureMapping2D::fromParams(r.params, r.textureToWorld), std::move(dot),
                                         std::move(background));
}

std::shared_ptr<const Texture> makeFbmTexture(const TextureRequest& r) {
    const int octaves = octavesParam(r.params);
    const float omega = float(r.params.getFloat("roughness", 0.5));
    return noise3D(r, [=](Vec3f p) { return fractionalBrownianMotion(p, omega, octaves); });
}

std::shared_ptr<const Texture> makeWrinkledTexture(const TextureRequest& r) {
    const int octaves = octavesParam(r.params);
    const float omega = float(r.params.getFloat("roughness", 0.5));
    return noise3D(r, [=](Vec3f p) { return turbulence(p, omega, octaves); });
}

// Wave height (6 octaves) scaled by a slowly varying wind strength (3 octaves at a tenth the
// frequency).
std::shared_ptr<const Texture> makeWindyTexture(const TextureRequest& r) {
    return noise3D(r, [](Vec3f p) {
        return std::fabs(fractionalBrownianMotion(0.1f * p, 0.5f, 3)) * fractionalBrownianMotion(p, 0.5f, 6);
    });
}

std::shared_ptr<const Texture> makeMarbleTexture(const TextureRequest& r) {
    const int octaves = octavesParam(r.params);
    return std::make_shared<MarbleTexture>(TextureMapping3D(r.textureToWorld), octaves,
                                           float(r.params.getFloat("roughness", 0.5)),
                                           float(r.params.getFloat("scale", 1)),
                                           float(r.params.getFloat("variation", 0.2)));
}

}  // namespace lenslab
