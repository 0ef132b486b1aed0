#pragma once
// PROVISIONAL (replaced by the glass branch).
#include <optional>
#include <string>
#include <vector>

#include "Medium.h"

namespace lenslab {

struct GlassLookup {
    std::optional<Medium> glass;
    std::vector<std::string> searched;
    std::vector<std::string> suggestions;
};
GlassLookup findGlass(const std::string& name, const std::vector<std::string>& preferredCatalogs = {});

}  // namespace lenslab
