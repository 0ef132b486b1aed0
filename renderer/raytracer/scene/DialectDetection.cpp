#include "scene/DialectDetection.h"

#include <map>
#include <set>
#include <string>

namespace lenslab {

namespace {

const std::set<std::string> kV4Materials = {"diffuse",    "coateddiffuse",  "coatedconductor",    "conductor",
                                            "dielectric", "thindielectric", "diffusetransmission"};

bool isV4Name(const std::string& directive, const std::string& name) {
    static const std::map<std::string, std::set<std::string>> kV4Names = {
        {"Material", kV4Materials},
        {"Film", {"rgb", "gbuffer", "spectral"}},
        {"Shape", {"bilinearmesh"}},
        {"Camera", {"spherical"}},
    };
    const auto it = kV4Names.find(directive);
    return it != kV4Names.end() && it->second.count(name);
}

}  // namespace

SceneDialect detectDialect(const std::vector<Token>& tokens) {
    static const std::set<std::string> kV4Directives = {"ColorSpace", "Option", "Attribute", "Import"};
    static const std::set<std::string> kV4Parameters = {"float power", "float illuminance"};
    for (std::size_t i = 0; i < tokens.size(); ++i) {
        const Token& t = tokens[i];
        if (!t.quoted) {
            if (kV4Directives.count(t.text)) return SceneDialect::PbrtV4;
            if (i + 1 < tokens.size() && tokens[i + 1].quoted && isV4Name(t.text, tokens[i + 1].text))
                return SceneDialect::PbrtV4;
            continue;
        }
        if (kV4Parameters.count(t.text)) return SceneDialect::PbrtV4;
        if (t.text == "string type") {  // MakeNamedMaterial's type, bracketed or not
            std::size_t v = i + 1;
            if (v < tokens.size() && !tokens[v].quoted && tokens[v].text == "[") ++v;
            if (v < tokens.size() && tokens[v].quoted && kV4Materials.count(tokens[v].text)) return SceneDialect::PbrtV4;
        }
    }
    return SceneDialect::PbrtV3;
}

}  // namespace lenslab
