#include "storage/DataFolderLock.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <stdexcept>

namespace lenslab {

DataFolderLock::DataFolderLock(const std::string& dataDir) {
    std::error_code error;
    std::filesystem::create_directories(dataDir, error);
    const std::string path = (std::filesystem::path(dataDir) / "lenslab.lock").string();
    fd_ = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd_ < 0)
        throw std::runtime_error("cannot write in the data folder " + dataDir + " (" + std::strerror(errno) +
                                 "); lenslab serve keeps its database and files there: make it writable or "
                                 "choose another with --data");
    if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
        const int reason = errno;
        ::close(fd_);
        throw std::runtime_error(reason == EWOULDBLOCK
                                     ? "the data folder " + dataDir + " is in use by another lenslab serve; stop it "
                                       "or give this one its own --data"
                                     : "cannot lock the data folder " + dataDir + ": " + std::strerror(reason));
    }
}

DataFolderLock::~DataFolderLock() { ::close(fd_); }

}  // namespace lenslab
