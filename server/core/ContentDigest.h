#pragma once
// SHA-256 of content, as 64 hex digits: what the service keys cached results by when they depend on
// a lens's text, not its id (two uploads of one table share their analyses). A cryptographic hash,
// so that nobody can make their lens's key collide with another's and be served its results.
#include <string>

namespace lenslab {

std::string contentDigest(const std::string& bytes);

}  // namespace lenslab
