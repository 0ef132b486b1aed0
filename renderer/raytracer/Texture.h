#pragma once
// Textures: colours as a function of the surface (u, v) coordinates.
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "ParamSet.h"
#include "Vec3f.h"

namespace lenslab {

class Texture {
public:
    virtual ~Texture() = default;
    virtual Vec3f evaluate(float u, float v) const = 0;
};

using TextureMap = std::map<std::string, std::shared_ptr<const Texture>>;

std::shared_ptr<const Texture> makeConstantTexture(Vec3f value);

// Texture "name" "spectrum"|"float" "CLASS" params: checkerboard, constant, imagemap (PNG).
std::shared_ptr<const Texture> makeTexture(const std::string& className, const ParamSet& params,
                                           const TextureMap& named, const PathResolver& resolve,
                                           std::vector<std::string>& warnings);

// A material parameter that is either a colour or the name of a declared texture.
std::shared_ptr<const Texture> textureParam(const ParamSet& params, const std::string& name, Vec3f fallback,
                                            const TextureMap& named);

}  // namespace lenslab
