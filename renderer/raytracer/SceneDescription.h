#pragma once
// A parsed scene: the rendering options from before WorldBegin and the world's shapes, materials
// and lights, all in world space (metres).
#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "Light.h"
#include "Material.h"
#include "ParamSet.h"
#include "Transform.h"

namespace lenslab {

struct CameraSpec {
    std::string type = "perspective";  // perspective | realistic
    ParamSet params;
    Transform cameraToWorld;
};

struct FilmSpec {
    int xresolution = 1280, yresolution = 720;
    std::string filename;                       // empty: none given
    double diagonalMm = 35;                     // pbrt-v3's Film "diagonal"
    std::array<double, 4> crop = {0, 1, 0, 1};  // x0, x1, y0, y1 in [0, 1]
    SourceLocation where;
};

enum class FilterType { Box, Gaussian };
struct FilterSpec {
    FilterType type = FilterType::Box;
    double xwidth = 0.5, ywidth = 0.5, alpha = 2;  // radii in pixels
};

struct IntegratorSpec {
    bool directOnly = false;  // "directlighting": light sampled at the first diffuse hit only
    int maxDepth = 5;
};

struct AreaEmission {
    Vec3f L;
    bool twoSided = false;
};

struct TriangleMesh {
    std::vector<Vec3f> p, n;        // world space; n empty or one per vertex
    std::vector<float> uv;          // 2 per vertex, or empty
    std::vector<std::uint32_t> indices;
    std::shared_ptr<const Material> material;
    std::optional<AreaEmission> emission;
    bool flipNormals = false;       // ReverseOrientation xor a handedness-swapping transform
};

struct Sphere {
    Transform objectToWorld;        // a similarity (uniform scale): the sphere stays a sphere
    Vec3f centre;
    float radius = 1;
    std::shared_ptr<const Material> material;
    std::optional<AreaEmission> emission;
    bool flipNormals = false;
};

struct SceneDescription {
    std::string file;      // the top-level scene file
    std::string rootDir;   // its folder: every file the scene names must lie inside
    CameraSpec camera;
    FilmSpec film;
    int pixelSamples = 16;
    FilterSpec filter;
    IntegratorSpec integrator;
    std::vector<TriangleMesh> meshes;
    std::vector<Sphere> spheres;
    std::vector<std::unique_ptr<Light>> lights;  // not the area lights (those come with shapes)
    std::vector<std::string> warnings;
};

// Reads a pbrt-v3 scene (the subset lenslab supports). Throws SceneError naming the file, line and
// directive for anything it cannot honour.
SceneDescription parseSceneFile(const std::string& path);

// A file named in the scene, resolved against the folder of the file that names it; SceneError when
// it escapes the scene's folder tree or does not exist.
std::string resolveScenePath(const std::string& rootDir, const std::string& fromFile, const std::string& name,
                             const SourceLocation& where);

}  // namespace lenslab
