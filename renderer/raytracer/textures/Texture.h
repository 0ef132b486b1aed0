#pragma once
// Textures: colours (or numbers) as a function of the surface point: its (u, v) coordinates, or
// its position for 3D textures. pbrt-v3's texture classes, parameters and defaults.
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/ParamSet.h"
#include "core/Transform.h"
#include "core/Vec3f.h"

namespace lenslab {

struct SurfaceHit;

// A texture's value at a surface point. Float textures return their value in all three channels.
class Texture {
public:
    virtual ~Texture() = default;
    virtual Vec3f evaluate(const SurfaceHit& hit) const = 0;
};

enum class TextureKind { Float, Spectrum };

// The textures declared so far. pbrt-v3 keeps float and spectrum textures apart: one name may
// denote one of each, and a parameter finds only textures of its own kind.
struct TextureMap {
    std::map<std::string, std::shared_ptr<const Texture>> floats, spectra;
};

using TexturePtr = std::shared_ptr<const Texture>;

std::shared_ptr<const Texture> makeConstantTexture(Vec3f value);

// Texture "name" "float"|"spectrum" "CLASS" params. `textureToWorld` is the current transform at
// the directive (3D textures and the spherical and cylindrical mappings work in its space).
std::shared_ptr<const Texture> makeTexture(const std::string& className, TextureKind kind, const ParamSet& params,
                                           const Transform& textureToWorld, const TextureMap& named,
                                           const PathResolver& resolve, std::vector<std::string>& warnings);

// A spectrum parameter of a material or texture: a colour, or the name of a spectrum texture.
std::shared_ptr<const Texture> textureParam(const ParamSet& params, const std::string& name, Vec3f fallback,
                                            const TextureMap& named);
// A float parameter: a number, or the name of a float texture (its value in all three channels).
std::shared_ptr<const Texture> floatTextureParam(const ParamSet& params, const std::string& name, float fallback,
                                                 const TextureMap& named);

}  // namespace lenslab
