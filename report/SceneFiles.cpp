#include "SceneFiles.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <regex>
#include <sstream>

namespace lenslab {

namespace fs = std::filesystem;

namespace {

std::string readText(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// The text with # comments removed (a # inside a quoted string is kept).
std::string withoutComments(const std::string& text) {
    std::string out;
    bool quoted = false, comment = false;
    for (char c : text) {
        if (comment) {
            if (c == '\n') comment = false, out += c;
            continue;
        }
        if (c == '"') quoted = !quoted;
        if (c == '#' && !quoted) {
            comment = true;
            continue;
        }
        out += c;
    }
    return out;
}

std::string leadingComments(const std::string& text) {
    std::istringstream in(text);
    std::string joined;
    for (std::string line; std::getline(in, line);) {
        const std::size_t hash = line.find_first_not_of(" \t\r");
        if (hash == std::string::npos || line[hash] != '#') break;
        const std::size_t start = line.find_first_not_of("# \t", hash);
        const std::size_t end = line.find_last_not_of(" \t\r");
        if (start == std::string::npos) continue;
        joined += (joined.empty() ? "" : " ") + line.substr(start, end - start + 1);
    }
    return joined;
}

int integerParameter(const std::string& code, const std::string& name) {
    const std::regex pattern("\"integer\\s+" + name + "\"\\s*\\[?\\s*(\\d+)");
    std::smatch m;
    return std::regex_search(code, m, pattern) ? std::stoi(m[1].str()) : 0;
}

// Adds `file` and, for scene files, every quoted name in it that is an existing file.
void collectFiles(const fs::path& file, std::vector<std::string>& files, bool& realistic) {
    const std::string path = file.lexically_normal().string();
    if (std::find(files.begin(), files.end(), path) != files.end()) return;
    files.push_back(path);
    if (file.extension() != ".pbrt") return;
    const std::string code = withoutComments(readText(file));
    static const std::regex camera(R"(\bCamera\s+"realistic")");
    realistic = realistic || std::regex_search(code, camera);
    static const std::regex quotedName("\"([^\"\\n]+)\"");
    for (std::sregex_iterator it(code.begin(), code.end(), quotedName), end; it != end; ++it) {
        std::error_code ec;
        const fs::path named = file.parent_path() / (*it)[1].str();
        if (fs::is_regular_file(named, ec)) collectFiles(named, files, realistic);
    }
}

}  // namespace

std::vector<SceneSource> listScenes(const std::string& sceneDir) {
    std::vector<SceneSource> scenes;
    std::error_code ec;
    static const std::regex worldBegin(R"(\bWorldBegin\b)");
    for (fs::recursive_directory_iterator it(sceneDir, ec), end; !ec && it != end; it.increment(ec)) {
        const fs::path& p = it->path();
        if (p.extension() != ".pbrt" || !it->is_regular_file()) continue;
        const std::string text = readText(p);
        const std::string code = withoutComments(text);
        if (!std::regex_search(code, worldBegin)) continue;  // a fragment for Include, not a scene
        SceneSource s;
        std::string id = p.lexically_relative(sceneDir).replace_extension().generic_string();
        std::replace(id.begin(), id.end(), '/', '-');
        s.id = id;
        s.path = p.string();
        s.description = leadingComments(text);
        s.xResolution = integerParameter(code, "xresolution");
        s.yResolution = integerParameter(code, "yresolution");
        collectFiles(p, s.files, s.realisticCamera);
        scenes.push_back(std::move(s));
    }
    std::sort(scenes.begin(), scenes.end(), [](const SceneSource& a, const SceneSource& b) { return a.id < b.id; });
    return scenes;
}

}  // namespace lenslab
