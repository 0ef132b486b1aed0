#pragma once
// A number for a JSON answer: JSON has no NaN or infinity, so a value that is not finite (an object
// at infinity, a quantity that does not exist for this lens) is written as null.
#include <cmath>

#include <nlohmann/json.hpp>

namespace lenslab {

inline nlohmann::json finiteOrNull(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

}  // namespace lenslab
