#include "TestScenes.h"

#include "scene/SceneDescription.h"

namespace lenslab::test {

std::string lensPath(const std::string& name) { return std::string(LENSLAB_SOURCE_DIR) + "/lenses/" + name; }

std::string courseCamera(const std::string& lens, const std::string& params) {
    return "Scale 1000 1000 1000\nCamera \"realistic\" \"string specfile\" \"" + lensPath(lens) + "\" " + params;
}

std::string sceneErrorOf(const std::string& path) {
    try {
        parseSceneFile(path);
    } catch (const SceneError& e) {
        return e.what();
    }
    return "(no error)";
}

RenderOutput render(const std::string& scene, int width, int height, int spp, RenderSettings s) {
    s.scenePath = scene;
    s.width = width;
    s.height = height;
    s.spp = spp;
    if (s.threads == 0) s.threads = 2;
    return renderScene(s);
}

}  // namespace lenslab::test
