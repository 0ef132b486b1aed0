#pragma once
// pbrt-v3's texture mappings: from a surface point to 2D texture coordinates (s, t) (uv,
// spherical, cylindrical, planar), or to a point in the texture's own space for 3D textures.
#include "core/ParamSet.h"
#include "core/Transform.h"
#include "core/Vec3f.h"

namespace lenslab {

struct SurfaceHit;

struct TexCoord {
    float s = 0, t = 0;
};

class TextureMapping2D {
public:
    // "string mapping" (uv by default) and that mapping's parameters; `textureToWorld` is the
    // current transform at the Texture directive.
    static TextureMapping2D fromParams(const ParamSet& params, const Transform& textureToWorld);
    TexCoord map(const SurfaceHit& hit) const;

private:
    enum class Kind { Uv, Spherical, Cylindrical, Planar };
    TextureMapping2D() = default;
    Kind kind_ = Kind::Uv;
    float uscale_ = 1, vscale_ = 1, udelta_ = 0, vdelta_ = 0;  // udelta_, vdelta_ also for planar
    Vec3f v1_{1, 0, 0}, v2_{0, 1, 0};                         // planar
    Transform worldToTexture_;                                 // spherical, cylindrical
};

// The hit point in the texture's space. pbrt-v3 hands the transform current at the Texture
// directive to its 3D mapping as world-to-texture, unlike its 2D mappings (and pbrt-v4), which
// invert it: `Scale 8 8 8` before an fbm makes its noise 8x finer. Scenes written for pbrt-v3 are
// tuned to that, so it is followed here.
class TextureMapping3D {
public:
    explicit TextureMapping3D(const Transform& directiveTransform) : worldToTexture_(directiveTransform) {}
    Vec3f map(const SurfaceHit& hit) const;

private:
    Transform worldToTexture_;
};

}  // namespace lenslab
