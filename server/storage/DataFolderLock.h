#pragma once
// One server per data folder: an exclusive flock on DATA/lenslab.lock, held for the service's
// life and dropped by the kernel when the process ends (also after kill -9). A second server on
// the same folder would otherwise mark the first one's running job interrupted and run its queue.
#include <string>

namespace lenslab {

class DataFolderLock {
public:
    // Creates the folder if needed and takes the lock; std::runtime_error when another process
    // holds it or the folder cannot be written.
    explicit DataFolderLock(const std::string& dataDir);
    ~DataFolderLock();
    DataFolderLock(const DataFolderLock&) = delete;
    DataFolderLock& operator=(const DataFolderLock&) = delete;

private:
    int fd_ = -1;
};

}  // namespace lenslab
