#pragma once
// The data folder's size against its quota (--max-data-gb): uploads and render submissions are
// refused with 507 while the folder is at or over it, and reads go on. Retention runs before a
// refusal, so finished renders it would collect anyway never block a write. Measuring walks the
// folder, so one measurement serves the requests of the next second.
#include <chrono>
#include <cstdint>
#include <functional>
#include <mutex>
#include <string>

namespace lenslab {

// `quota` lowered, when the disk holds less, to the folder's size plus the disk's free space.
std::uintmax_t quotaWithinDisk(const std::string& folder, std::uintmax_t quota);

class DataFolderQuota {
public:
    // maxBytes 0: no quota. collect() applies the retention policy.
    DataFolderQuota(std::string folder, std::uintmax_t maxBytes, std::function<void()> collect);

    // HttpError 507, with what to do and the sizes in MB, when the folder is at or over the quota.
    void checkRoomForWrite();

private:
    std::uintmax_t measuredBytes(bool fresh);

    std::string folder_;
    std::uintmax_t maxBytes_;
    std::function<void()> collect_;
    std::mutex mutex_;
    std::uintmax_t bytes_ = 0;
    std::chrono::steady_clock::time_point measuredAt_{};
    bool measured_ = false;
};

}  // namespace lenslab
