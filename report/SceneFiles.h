#pragma once
// The bundled scenes as the report sees them: which have a realistic camera (the lens overrides
// apply only to those), and which files each depends on, for the render cache.
#include <string>
#include <vector>

namespace lenslab {

struct SceneSource {
    std::string id;                  // path below the scene folder without .pbrt, '/' as '-'
                                     // (course/x.pbrt: course-x)
    std::string description;         // the leading comment lines, joined
    std::string path;
    bool realisticCamera = false;
    int xResolution = 0, yResolution = 0;  // the Film's, 0 when not given
    std::vector<std::string> files;  // the scene file and every existing file it names (includes,
                                     // meshes, textures), followed recursively through .pbrt files
};

// Every scene file (.pbrt with a WorldBegin) in <dir> and its subfolders, sorted by id; fragments
// made to be included (world/*.pbrt) are not scenes. Missing folder: none.
std::vector<SceneSource> listScenes(const std::string& sceneDir);

}  // namespace lenslab
