#include "storage/SceneCatalog.h"

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "core/Identifiers.h"

namespace lenslab {

namespace fs = std::filesystem;

namespace {

std::string firstCommentLine(const fs::path& file) {
    std::ifstream in(file);
    std::string line;
    while (std::getline(in, line)) {
        const auto start = line.find_first_not_of(" \t\r");
        if (start == std::string::npos) continue;
        if (line[start] != '#') return "";
        const auto text = line.find_first_not_of("# \t", start);
        if (text == std::string::npos) continue;
        std::string title = line.substr(text);
        while (!title.empty() && (title.back() == '\r' || title.back() == ' ')) title.pop_back();
        return title;
    }
    return "";
}

}  // namespace

SceneCatalog::SceneCatalog(const std::string& folder) {
    std::error_code ec;
    for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
        const fs::path& p = it->path();
        if (p.extension() != ".pbrt" || !isSafeIdentifier(p.stem().string())) continue;
        scenes_.push_back({p.stem().string(), firstCommentLine(p), p.string()});
    }
    std::sort(scenes_.begin(), scenes_.end(), [](const SceneEntry& a, const SceneEntry& b) { return a.id < b.id; });
}

std::optional<SceneEntry> SceneCatalog::find(const std::string& id) const {
    for (const SceneEntry& s : scenes_)
        if (s.id == id) return s;
    return std::nullopt;
}

}  // namespace lenslab
