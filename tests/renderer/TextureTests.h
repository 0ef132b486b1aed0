#pragma once
// Helpers for texture tests: parameter lists built in code, textures made from them and evaluated
// at chosen surface points.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "materials/Material.h"
#include "Render.h"
#include "SceneParams.h"
#include "textures/Texture.h"

namespace lenslab::test {

// Resolves names as paths; a missing file fails the way the scene parser's resolver does.
inline std::string resolveAsIs(const std::string& name, const SourceLocation& where) {
    if (!std::filesystem::is_regular_file(name)) sceneFail(where, "cannot open '" + name + "'");
    return name;
}

inline std::shared_ptr<const Texture> texture(const std::string& cls, std::vector<Param> params,
                                              TextureKind kind = TextureKind::Spectrum,
                                              const Transform& textureToWorld = {}, const TextureMap& named = {}) {
    std::vector<std::string> warnings;
    const ParamSet p(SourceLocation{"test.pbrt", 1, "Texture"}, std::move(params));
    auto t = makeTexture(cls, kind, p, textureToWorld, named, resolveAsIs, warnings);
    for (const std::string& w : warnings) ADD_FAILURE() << "unexpected warning: " << w;
    return t;
}

inline SurfaceHit hitAt(float u, float v, Vec3f p = {}) {
    SurfaceHit h;
    h.p = p;
    h.u = u;
    h.v = v;
    return h;
}

inline void expectRgb(Vec3f got, Vec3f want, float tol = 1e-6f) {
    EXPECT_NEAR(got.x, want.x, tol);
    EXPECT_NEAR(got.y, want.y, tol);
    EXPECT_NEAR(got.z, want.z, tol);
}

}  // namespace lenslab::test
