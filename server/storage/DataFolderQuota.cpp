#include "storage/DataFolderQuota.h"

#include <algorithm>
#include <filesystem>
#include <sstream>

#include "core/HttpError.h"

namespace lenslab {

namespace {

namespace fs = std::filesystem;

constexpr std::chrono::seconds kMeasurementLife{1};

// Files that vanish while the folder is walked (renders collected, temporaries renamed) are skipped.
std::uintmax_t folderBytes(const std::string& folder) {
    std::uintmax_t total = 0;
    std::error_code error;
    for (auto it = fs::recursive_directory_iterator(folder, fs::directory_options::skip_permission_denied, error);
         !error && it != fs::recursive_directory_iterator(); it.increment(error)) {
        std::error_code fileError;
        if (it->is_regular_file(fileError)) {
            const std::uintmax_t size = it->file_size(fileError);
            if (!fileError) total += size;
        }
    }
    return total;
}

std::string megabytes(std::uintmax_t bytes) {
    std::ostringstream text;
    text.precision(bytes < 10'000'000 ? 2 : 0);
    text << std::fixed << bytes / 1e6 << " MB";
    return text.str();
}

}  // namespace

std::uintmax_t quotaWithinDisk(const std::string& folder, std::uintmax_t quota) {
    std::error_code error;
    const fs::space_info space = fs::space(folder, error);
    if (error) return quota;
    return std::min(quota, folderBytes(folder) + space.available);
}

DataFolderQuota::DataFolderQuota(std::string folder, std::uintmax_t maxBytes, std::function<void()> collect)
    : folder_(std::move(folder)), maxBytes_(maxBytes), collect_(std::move(collect)) {}

std::uintmax_t DataFolderQuota::measuredBytes(bool fresh) {
    const auto now = std::chrono::steady_clock::now();
    if (fresh || !measured_ || now - measuredAt_ >= kMeasurementLife) {
        bytes_ = folderBytes(folder_);
        measuredAt_ = now;
        measured_ = true;
    }
    return bytes_;
}

void DataFolderQuota::checkRoomForWrite() {
    if (maxBytes_ == 0) return;
    std::lock_guard<std::mutex> lock(mutex_);
    if (measuredBytes(false) < maxBytes_) return;
    collect_();
    const std::uintmax_t used = measuredBytes(true);
    if (used < maxBytes_) return;
    throw HttpError(507, "the server's data folder has reached its quota (" + megabytes(used) + " used of " +
                             megabytes(maxBytes_) + "); delete finished renders (DELETE /api/renders/{id}) or "
                             "uploaded lenses (DELETE /api/lenses/{id}), or ask the operator to raise --max-data-gb, "
                             "then try again");
}

}  // namespace lenslab
