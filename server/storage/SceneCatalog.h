#pragma once
// The bundled scenes: scenes/<id>.pbrt, id = file name without extension. A scene is only ever
// resolved by id inside this folder.
#include <optional>
#include <string>
#include <vector>

namespace lenslab {

struct SceneEntry {
    std::string id;
    std::string title;  // the scene file's first comment line
    std::string path;
};

class SceneCatalog {
public:
    explicit SceneCatalog(const std::string& folder);
    const std::vector<SceneEntry>& list() const { return scenes_; }
    std::optional<SceneEntry> find(const std::string& id) const;

private:
    std::vector<SceneEntry> scenes_;
};

}  // namespace lenslab
