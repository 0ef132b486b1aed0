#pragma once
// Identifiers that name lenses, scenes and jobs. They become file names inside the data folders,
// so only a conservative alphabet is accepted: no separators, no leading dot, bounded length.
#include <string>

namespace lenslab {

// [A-Za-z0-9][A-Za-z0-9._-]{0,79}
bool isSafeIdentifier(const std::string& id);

// prefix + 16 random hex digits.
std::string newRandomIdentifier(const std::string& prefix);

}  // namespace lenslab
