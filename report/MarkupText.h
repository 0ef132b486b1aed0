#pragma once
// Text made safe for HTML and SVG.
#include <string>

namespace lenslab {

// Escapes & < > " ' for use in element content and attribute values.
std::string escapeMarkup(const std::string& text);

}  // namespace lenslab
