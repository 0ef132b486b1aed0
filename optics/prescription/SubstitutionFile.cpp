#include "prescription/SubstitutionFile.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <regex>

#include <nlohmann/json.hpp>

#include "prescription/GlassCatalog.h"

namespace lenslab {

namespace {

// The line of the file on which an entry's name first appears (1 when it cannot be told).
int lineOf(const std::string& text, const std::string& key) {
    const std::size_t at = text.find("\"" + key + "\"");
    if (at == std::string::npos) return 1;
    return 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(at), '\n'));
}

// refractiveindex.info pages the bundled MISC catalog was made from (scripts/make-glass-catalog.py).
std::optional<std::string> bundledMaterial(const std::string& url) {
    static const std::pair<const char*, const char*> kPages[] = {
        {"main/SiO2/", "SILICA"}, {"main/CaF2/", "CAF2"}, {"main/BaF2/", "BAF2"},
        {"main/Al2O3/", "SAPPHIRE"}, {"main/MgF2/", "MGF2"}};
    for (const auto& [page, glass] : kPages)
        if (url.find(page) != std::string::npos) return std::string(glass);
    return std::nullopt;
}

GlassSubstitute fromExpression(const std::string& key, const std::string& expression, const std::string& where) {
    GlassSubstitute s;
    s.name = key;
    s.source = where;
    std::smatch m;
    const std::string number = R"([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)";
    if (std::regex_search(expression, m, std::regex(R"(ConstantIndex\(\s*()" + number + R"())"))) {
        Medium medium = constantIndex(std::strtod(m[1].str().c_str(), nullptr));
        medium.name = key;
        s.medium = medium;
        return s;
    }
    if (expression.find("InterpolatedMedium") != std::string::npos) {
        std::vector<std::array<double, 2>> pairs;
        const std::regex pair(R"(\(\s*()" + number + R"()\s*,\s*()" + number + R"()\s*\))");
        for (auto it = std::sregex_iterator(expression.begin(), expression.end(), pair); it != std::sregex_iterator(); ++it)
            pairs.push_back({std::strtod((*it)[1].str().c_str(), nullptr), std::strtod((*it)[2].str().c_str(), nullptr)});
        s.medium = tabulatedMedium(key, pairs);
        return s;
    }
    if (expression.find("create_glass") != std::string::npos) {
        if (const auto glass = bundledMaterial(expression)) {
            s.glass = *glass;
            s.catalog = "MISC";
            return s;
        }
        throw std::invalid_argument("names a refractiveindex.info page lenslab does not bundle (it reads no network)");
    }
    throw std::invalid_argument("is not a glass and catalog, ConstantIndex, InterpolatedMedium or create_glass");
}

}  // namespace

std::vector<GlassSubstitute> parseSubstitutionFile(const std::string& text, const std::string& fileName) {
    nlohmann::json j;
    try {
        j = nlohmann::json::parse(text);
    } catch (const nlohmann::json::parse_error& e) {
        throw LensTableError(fileName, 0, std::string("not JSON: ") + e.what());
    }
    if (!j.is_object()) throw LensTableError(fileName, 1, "a substitution table is a JSON object of glass names");
    std::vector<GlassSubstitute> table;
    for (const auto& [key, value] : j.items()) {
        const int line = lineOf(text, key);
        const std::string where = fileName + ":" + std::to_string(line);
        try {
            if (value.is_array() && !value.empty() && value.size() <= 2 && value[0].is_string() &&
                (value.size() == 1 || value[1].is_string())) {
                GlassSubstitute s;
                s.name = key;
                s.glass = value[0].get<std::string>();
                if (value.size() == 2) s.catalog = value[1].get<std::string>();
                s.source = where;
                table.push_back(s);
            } else if (value.is_string()) {
                table.push_back(fromExpression(key, value.get<std::string>(), where));
            } else {
                throw std::invalid_argument("is neither [glass, catalog] nor an expression");
            }
        } catch (const std::invalid_argument& e) {
            throw LensTableError(fileName, line, "substitute for '" + key + "' " + e.what());
        }
    }
    return table;
}

std::optional<std::string> substitutionFileFor(const std::string& prescriptionPath) {
    std::filesystem::path p(prescriptionPath);
    p.replace_extension(".smx");
    std::error_code error;
    if (std::filesystem::is_regular_file(p, error)) return p.string();
    return std::nullopt;
}

}  // namespace lenslab
