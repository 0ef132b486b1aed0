#include "storage/StorageError.h"

#include <cerrno>

namespace lenslab {

namespace {

const char* messageFor(StorageError::Kind kind) {
    switch (kind) {
        case StorageError::Kind::Full:
            return "the server's data folder is full; delete finished renders (DELETE /api/renders/{id}) or uploaded "
                   "lenses, or ask the operator to free disk space, then try again";
        case StorageError::Kind::ReadOnly:
            return "the server's data folder cannot be written (read-only or no permission); ask the operator to "
                   "make it writable, then try again";
        case StorageError::Kind::Failed: break;
    }
    return "the server could not write to its data folder (an I/O error); try again later or ask the operator";
}

}  // namespace

StorageError::StorageError(Kind kind, std::string detail)
    : std::runtime_error(messageFor(kind)), kind_(kind), detail_(std::move(detail)) {}

StorageError::Kind storageErrorKind(int errorNumber) {
    switch (errorNumber) {
        case ENOSPC:
        case EDQUOT:
        case EFBIG: return StorageError::Kind::Full;
        case EROFS:
        case EACCES:
        case EPERM: return StorageError::Kind::ReadOnly;
        default: return StorageError::Kind::Failed;
    }
}

}  // namespace lenslab
