#include "storage/AtomicFile.h"

#include "storage/StorageError.h"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace lenslab {

namespace {

const char* kTemporaryMarker = ".partial-";

StorageError fileError(const std::string& what, const std::string& path) {
    return StorageError(storageErrorKind(errno), what + " " + path + ": " + std::strerror(errno));
}

void writeAll(int fd, const char* data, std::size_t size, const std::string& path) {
    while (size > 0) {
        const ssize_t n = ::write(fd, data, size);
        if (n < 0) {
            if (errno == EINTR) continue;
            throw fileError("cannot write", path);
        }
        data += n;
        size -= static_cast<std::size_t>(n);
    }
}

void syncFolder(const std::filesystem::path& folder) {
    const int fd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY);
    if (fd < 0) return;
    ::fsync(fd);
    ::close(fd);
}

void writeBytesAtomically(const std::string& path, const char* data, std::size_t size) {
    static std::atomic<unsigned> counter{0};
    const std::filesystem::path target(path);
    std::error_code folderError;
    std::filesystem::create_directories(target.parent_path(), folderError);
    if (folderError)
        throw StorageError(storageErrorKind(folderError.value()),
                           "cannot create " + target.parent_path().string() + ": " + folderError.message());
    const std::string temporary = path + kTemporaryMarker + std::to_string(::getpid()) + "-" + std::to_string(counter++);
    const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd < 0) throw fileError("cannot create", temporary);
    try {
        writeAll(fd, data, size, temporary);
        if (::fsync(fd) != 0) throw fileError("cannot flush", temporary);
    } catch (...) {
        ::close(fd);
        ::unlink(temporary.c_str());
        throw;
    }
    ::close(fd);
    if (::rename(temporary.c_str(), path.c_str()) != 0) {
        const StorageError error = fileError("cannot rename onto", path);
        ::unlink(temporary.c_str());
        throw error;
    }
    syncFolder(target.parent_path());
}

}  // namespace

void writeFileAtomically(const std::string& path, const std::string& bytes) {
    writeBytesAtomically(path, bytes.data(), bytes.size());
}

void writeFileAtomically(const std::string& path, const std::vector<std::uint8_t>& bytes) {
    writeBytesAtomically(path, reinterpret_cast<const char*>(bytes.data()), bytes.size());
}

int removeStaleTemporaries(const std::string& folder) {
    namespace fs = std::filesystem;
    std::error_code ec;
    if (!fs::is_directory(folder, ec)) return 0;
    std::vector<fs::path> stale;
    for (fs::recursive_directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec))
        if (it->is_regular_file(ec) && it->path().filename().string().find(kTemporaryMarker) != std::string::npos)
            stale.push_back(it->path());
    for (const fs::path& p : stale) fs::remove(p, ec);
    return static_cast<int>(stale.size());
}

std::string readWholeFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error("cannot read " + path);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

}  // namespace lenslab
