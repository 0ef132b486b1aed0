#pragma once
// Writing to the data folder failed for a reason only the operator can fix: the disk or quota is
// full (HTTP 507), or the folder is read-only or not writable (503). The message tells the user
// what happened and what to do, and names no path of the server's file system; detail() keeps
// the system's own wording (with the path) for the server's log.
#include <stdexcept>
#include <string>

namespace lenslab {

class StorageError : public std::runtime_error {
public:
    enum class Kind { Full, ReadOnly, Failed };
    StorageError(Kind kind, std::string detail);

    Kind kind() const { return kind_; }
    int httpStatus() const { return kind_ == Kind::Full ? 507 : 503; }
    const std::string& detail() const { return detail_; }

private:
    Kind kind_;
    std::string detail_;
};

// The kind of failure an errno from a write means.
StorageError::Kind storageErrorKind(int errorNumber);

}  // namespace lenslab
