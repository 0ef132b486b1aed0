#include "textures/TextureMapping.h"

#include <cmath>

#include "core/Pi.h"
#include "materials/Material.h"

namespace lenslab {

namespace {

// The unit direction from the texture space's origin to the hit; the origin itself (where pbrt
// would divide by zero) maps to +z.
Vec3f directionInTextureSpace(const Transform& worldToTexture, Vec3f p) {
    const Vec3f d = transformPoint(worldToTexture, p);
    const float len = length(d);
    return len > 0 ? d / len : Vec3f{0, 0, 1};
}

// atan2 in [0, 2 pi).
float azimuth(Vec3f d) {
    const float phi = std::atan2(d.y, d.x);
    return phi < 0 ? phi + 2 * kPif : phi;
}

}  // namespace

TextureMapping2D TextureMapping2D::fromParams(const ParamSet& p, const Transform& textureToWorld) {
    TextureMapping2D m;
    const std::string kind = p.getString("mapping", "uv");
    if (kind == "uv") {
        m.kind_ = Kind::Uv;
        m.uscale_ = float(p.getFloat("uscale", 1));
        m.vscale_ = float(p.getFloat("vscale", 1));
    } else if (kind == "spherical" || kind == "cylindrical") {
        m.kind_ = kind == "spherical" ? Kind::Spherical : Kind::Cylindrical;
        m.worldToTexture_ = inverse(textureToWorld);
        return m;
    } else if (kind == "planar") {
        m.kind_ = Kind::Planar;
        m.v1_ = p.getPoint("v1", {1, 0, 0});
        m.v2_ = p.getPoint("v2", {0, 1, 0});
    } else {
        p.fail("texture mapping \"" + kind + "\" is not one of uv, spherical, cylindrical, planar");
    }
    m.udelta_ = float(p.getFloat("udelta", 0));
    m.vdelta_ = float(p.getFloat("vdelta", 0));
    return m;
}

TexCoord TextureMapping2D::map(const SurfaceHit& hit) const {
    switch (kind_) {
        case Kind::Uv:
            return {uscale_ * hit.u + udelta_, vscale_ * hit.v + vdelta_};
        case Kind::Spherical: {  // s: polar angle from +z, t: azimuth, both as fractions
            const Vec3f d = directionInTextureSpace(worldToTexture_, hit.p);
            return {std::acos(std::fmax(-1.0f, std::fmin(1.0f, d.z))) / kPif, azimuth(d) / (2 * kPif)};
        }
        case Kind::Cylindrical: {  // s: azimuth measured from -x; t: the unit direction's z, as pbrt-v3
            const Vec3f d = directionInTextureSpace(worldToTexture_, hit.p);
            return {(kPif + std::atan2(d.y, d.x)) / (2 * kPif), d.z};
        }
        case Kind::Planar:  // pbrt-v3 projects the world-space point, whatever the transform
            return {udelta_ + dot(hit.p, v1_), vdelta_ + dot(hit.p, v2_)};
    }
    return {};
}

Vec3f TextureMapping3D::map(const SurfaceHit& hit) const { return transformPoint(worldToTexture_, hit.p); }

}  // namespace lenslab
