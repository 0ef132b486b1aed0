#pragma once
// Text made safe for HTML and SVG, and numbers written the way the report shows them.
#include <string>

namespace lenslab {

// Escapes & < > " ' for use in element content and attribute values.
std::string escapeMarkup(const std::string& text);

// Fixed-point with `decimals` digits ("-0.000" written as "0.000"); non-finite values as an en dash.
std::string fixedNumber(double value, int decimals);

}  // namespace lenslab
