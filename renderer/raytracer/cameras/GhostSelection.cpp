#include "cameras/GhostSelection.h"

#include <cstdlib>

namespace lenslab {

namespace {

constexpr int kMostGhosts = 1000;

}  // namespace

std::optional<GhostSelection> parseGhostSelection(const std::string& text) {
    GhostSelection s;
    if (text == "off") return s;
    if (text == "auto" || text == "all") {
        s.mode = text == "auto" ? GhostSelection::Mode::Auto : GhostSelection::Mode::All;
        return s;
    }
    if (text.empty() || text.size() > 4 || text.find_first_not_of("0123456789") != std::string::npos) return std::nullopt;
    s.count = std::atoi(text.c_str());
    if (s.count < 1 || s.count > kMostGhosts) return std::nullopt;
    s.mode = GhostSelection::Mode::Brightest;
    return s;
}

std::optional<GhostModel> parseGhostModel(const std::string& text) {
    if (text == "exact") return GhostModel::Exact;
    if (text == "paraxial") return GhostModel::Paraxial;
    return std::nullopt;
}

std::string ghostSelectionName(const GhostSelection& s) {
    switch (s.mode) {
        case GhostSelection::Mode::Off: return "off";
        case GhostSelection::Mode::Auto: return "auto";
        case GhostSelection::Mode::All: return "all";
        case GhostSelection::Mode::Brightest: return std::to_string(s.count);
    }
    return "off";
}

const char* ghostModelName(GhostModel model) { return model == GhostModel::Exact ? "exact" : "paraxial"; }

std::string badGhostsMessage(const std::string& text) {
    return "ghosts must be off, auto, all or a number of ghosts from 1 to 1000, got '" + text.substr(0, 40) + "'";
}

std::string badGhostModelMessage(const std::string& text) {
    return "ghost model must be exact or paraxial, got '" + text.substr(0, 40) + "'";
}

}  // namespace lenslab
