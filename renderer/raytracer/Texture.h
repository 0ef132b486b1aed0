#pragma once
// Textures: colours (or numbers) as a function of the surface point: its (u, v) coordinates, or
// its position for 3D textures.
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "ParamSet.h"
#include "Vec3f.h"

namespace lenslab {

struct SurfaceHit;

// A texture's value at a surface point. Float textures return their value in all three channels.
class Texture {
public:
    virtual ~Texture() = default;
    virtual Vec3f evaluate(const SurfaceHit& hit) const = 0;
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
