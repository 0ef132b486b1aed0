#pragma once
// A parsed scene: the rendering options from before WorldBegin and the world's shapes, materials
// and lights, all in world space (metres).
#include <array>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "lights/Light.h"
#include "materials/Material.h"
#include "media/ParticipatingMedium.h"
#include "core/ParamSet.h"
#include "core/SceneDialect.h"
#include "shapes/Shape.h"
#include "core/AnimatedTransform.h"

namespace lenslab {

struct CameraSpec {
    std::string type = "perspective";  // perspective | realistic
    ParamSet params;
    AnimatedTransform cameraToWorld;  // pbrt's CameraToWorld at the two transform times
    std::shared_ptr<const ParticipatingMedium> medium;  // where camera rays start; null: vacuum
};

struct FilmSpec {
    int xresolution = 1280, yresolution = 720;
    std::string filename;                       // empty: none given
    double diagonalMm = 35;                     // pbrt-v3's Film "diagonal"
    std::array<double, 4> crop = {0, 1, 0, 1};  // x0, x1, y0, y1 in [0, 1]
    double scale = 1;                           // pbrt-v3's Film "scale": multiplies every pixel
    double maxSampleLuminance = 0;              // > 0: clamp each sample's luminance to this (pbrt-v3)
    double maxComponentValue = 0;               // > 0: scale each sample down to this largest component (pbrt-v4)
    double iso = 100;                           // pbrt-v4's sensor: the image scales by ISO / 100
    double whiteBalanceKelvin = 0;              // pbrt-v4: adapt this illuminant's white to D65 (0: none)
    std::string cameraSensor;                   // pbrt-v4's measured camera (core/CameraSensorCurves.h); empty: CIE 1931
    SourceLocation where;
};

// pbrt-v3's pixel filters with their parameters; widths are radii in pixels.
enum class FilterType { Box, Gaussian, Triangle, Mitchell, Sinc };
struct FilterSpec {
    FilterType type = FilterType::Box;
    double xwidth = 0.5, ywidth = 0.5;
    double alpha = 2;        // gaussian
    double B = 1.0 / 3, C = 1.0 / 3;  // mitchell
    double tau = 3;          // sinc (Lanczos windowed)
};

// path: unidirectional with next-event estimation and MIS. directlighting: light sampled at the
// first non-specular hit, specular bounces followed. whitted: every light sampled at each hit,
// perfect specular reflection and refraction followed (pbrt-v3's WhittedIntegrator). volpath: path
// with participating media (scattering in volumes, light sampled through them).
enum class IntegratorType { Path, DirectLighting, Whitted, VolPath };
struct IntegratorSpec {
    IntegratorType type = IntegratorType::Path;
    int maxDepth = 5;
};

struct AreaEmission {
    Vec3f L;
    bool twoSided = false;
};

// A shape with its look: material, for an emitter its diffuse area light, and the media on its sides.
struct ShapeEntry {
    std::shared_ptr<const Shape> shape;
    std::shared_ptr<const Material> material;
    std::optional<AreaEmission> emission;
    MediumInterface media;
};

// ObjectBegin "name" ... ObjectEnd: shapes in the object's own space, drawn by every ObjectInstance.
struct ObjectDefinition {
    std::string name;
    std::vector<ShapeEntry> shapes;
};

// An ObjectInstance, or a moving world shape (placed, as in pbrt, by an instance of a one-shape object).
struct ObjectInstance {
    std::size_t object = 0;              // index into SceneDescription::objects
    AnimatedTransform instanceToWorld;   // the current transforms at ObjectInstance
};

struct SceneDescription {
    std::string file;      // the top-level scene file
    std::string rootDir;   // its folder: relative file names in the scene resolve against it (as pbrt-v3's)
    bool confined = false; // files must lie inside rootDir (scenes reached through the HTTP service)
    SceneDialect dialect = SceneDialect::PbrtV3;  // scene/DialectDetection.h
    CameraSpec camera;
    TransformTimes transformTimes;  // when the current transforms of ActiveTransform StartTime and EndTime hold
    FilmSpec film;
    int pixelSamples = 16;
    FilterSpec filter;
    IntegratorSpec integrator;
    std::vector<ShapeEntry> shapes;          // world space
    std::vector<ObjectDefinition> objects;
    std::vector<ObjectInstance> instances;
    std::vector<std::unique_ptr<Light>> lights;  // not the area lights (those come with shapes)
    std::vector<std::string> warnings;
};

struct SceneParseOptions {
    bool confined = false;                        // refuse files outside the scene's folder tree
    std::function<void(double fraction)> progress; // called as the main file is read, 0 to 1
    bool optionsOnly = false;  // stop at WorldBegin: the camera, film and sampler without the world
};

// Reads a pbrt-v3 scene. Throws SceneError naming the file, line and directive for anything whose
// omission would change the picture in a way the user must know; warns (scene.warnings) otherwise.
SceneDescription parseSceneFile(const std::string& path, const SceneParseOptions& options = {});

// A file the scene names, resolved as pbrt-v3 does: absolute, or relative to the main scene file's
// folder. SceneError naming the path tried when it does not exist, or when the scene is confined
// and the file lies outside its folder tree.
std::string resolveScenePath(const SceneDescription& scene, const std::string& name, const SourceLocation& where);

}  // namespace lenslab
