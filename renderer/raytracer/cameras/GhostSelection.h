#pragma once
// Which ghosts a render models (cameras/LensFlare.h): none ("off", the default), every ghost
// ("all"), the N brightest by the ghost analysis ("N"), or every ghost but only when an emitter
// brighter than the flare threshold is in or near the frame ("auto": what the scene requires, and
// nothing, the same image bit for bit, when it requires none); and their model, the exact trace or
// the paraxial matrices. A realistic camera takes them as its "ghosts" and "ghostmodel" parameters
// (lenslab's own), which the render settings override.
#include <cstdint>
#include <optional>
#include <string>

namespace lenslab {

enum class GhostModel : std::uint8_t { Exact, Paraxial };

struct GhostSelection {
    enum class Mode { Off, Auto, All, Brightest } mode = Mode::Off;
    int count = 0;  // Brightest: how many
    GhostModel model = GhostModel::Exact;
    bool on() const { return mode != Mode::Off; }
};

// "off" | "auto" | "all" | a whole number 1..1000; nullopt otherwise.
std::optional<GhostSelection> parseGhostSelection(const std::string& text);
std::optional<GhostModel> parseGhostModel(const std::string& text);  // "exact" | "paraxial"
std::string ghostSelectionName(const GhostSelection& selection);      // as parsed: "off", "auto", "all", "12"
const char* ghostModelName(GhostModel model);

// The messages of a text neither parse takes.
std::string badGhostsMessage(const std::string& text);
std::string badGhostModelMessage(const std::string& text);

}  // namespace lenslab
