#pragma once
// Files the service writes (uploaded lenses, rendered images) appear complete or not at all: the
// bytes go to a temporary name in the same folder, are flushed, then renamed over the target.
#include <cstdint>
#include <string>
#include <vector>

namespace lenslab {

// StorageError when the folder is full, read-only or fails.
void writeFileAtomically(const std::string& path, const std::string& bytes);
void writeFileAtomically(const std::string& path, const std::vector<std::uint8_t>& bytes);

// Removes temporaries left by a process that died mid-write (anything under `folder`, recursively,
// whose name carries the temporary marker). Returns how many were removed.
int removeStaleTemporaries(const std::string& folder);

// The whole file; std::runtime_error when it cannot be read.
std::string readWholeFile(const std::string& path);

}  // namespace lenslab
