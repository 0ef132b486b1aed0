#pragma once
// The texture classes, each made from its Texture directive (internal to the texture sources;
// makeTexture in Texture.h picks one by class name).
#include <memory>
#include <string>
#include <vector>

#include "textures/Texture.h"

namespace lenslab {

struct TextureRequest {
    const ParamSet& params;
    TextureKind kind;
    const Transform& textureToWorld;
    const TextureMap& named;
    const PathResolver& resolve;
    std::vector<std::string>& warnings;

    // A parameter of the texture's own kind (tex1, tex2, ...): a value or a declared texture.
    std::shared_ptr<const Texture> operand(const std::string& name, float fallback) const;
    // A plain value of the texture's own kind: a float (as grey) or a colour.
    Vec3f value(const std::string& name, float fallback) const;
};

std::shared_ptr<const Texture> makeScaleTexture(const TextureRequest& r);
std::shared_ptr<const Texture> makeMixTexture(const TextureRequest& r);
std::shared_ptr<const Texture> makeBilerpTexture(const TextureRequest& r);
std::shared_ptr<const Texture> makeUvTexture(const TextureRequest& r);
std::shared_ptr<const Texture> makeCheckerboardTexture(const TextureRequest& r);
std::shared_ptr<const Texture> makeDotsTexture(const TextureRequest& r);
std::shared_ptr<const Texture> makeFbmTexture(const TextureRequest& r);
std::shared_ptr<const Texture> makeWrinkledTexture(const TextureRequest& r);
std::shared_ptr<const Texture> makeWindyTexture(const TextureRequest& r);
std::shared_ptr<const Texture> makeMarbleTexture(const TextureRequest& r);
std::shared_ptr<const Texture> makeImageTexture(const TextureRequest& r);

}  // namespace lenslab
