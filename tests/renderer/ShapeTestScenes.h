#pragma once
// Helpers for the shape, instancing and mesh tests: a world block written into a scene with a
// 64x64 perspective camera at the origin looking down +z (y up, fov 40), parsed, and turned into
// Embree geometry.
#include <limits>
#include <memory>
#include <string>

#include "scene/SceneDescription.h"
#include "geometry/SceneGeometry.h"
#include "TestScenes.h"

namespace lenslab::test {

inline std::string shapeScene(const TempDir& dir, const std::string& world, const std::string& name = "s.pbrt") {
    return dir.write(name, "LookAt 0 0 0  0 0 1  0 1 0\nCamera \"perspective\" \"float fov\" 40\n"
                           "Film \"image\" \"integer xresolution\" 64 \"integer yresolution\" 64\n"
                           "WorldBegin\n" + world + "\nWorldEnd\n");
}

inline SceneDescription parseWorld(const TempDir& dir, const std::string& world) {
    return parseSceneFile(shapeScene(dir, world));
}

inline std::unique_ptr<SceneGeometry> geometryOf(const TempDir& dir, const std::string& world) {
    SceneDescription scene = parseWorld(dir, world);
    return std::make_unique<SceneGeometry>(scene);
}

inline bool trace(const SceneGeometry& g, Vec3f o, Vec3f d, Intersection& it) {
    return g.intersect(o, normalize(d), std::numeric_limits<float>::infinity(), 0, it);
}

// Pixels whose mean of R, G, B exceeds `threshold`, in rows [y0, y1).
inline int brightPixels(const Image& im, float threshold, int y0 = 0, int y1 = -1) {
    if (y1 < 0) y1 = im.height;
    int n = 0;
    for (int y = y0; y < y1; ++y)
        for (int x = 0; x < im.width; ++x) n += lum(im, x, y) > threshold;
    return n;
}

// The camera's 64 pixels span 2 tan(20 degrees) at unit distance.
inline double pixelsPerUnitAt(double distance) { return 64.0 / (2 * std::tan(20 * M_PI / 180) * distance); }

}  // namespace lenslab::test
