#include "guards/AccessLog.h"

#include <chrono>
#include <ctime>
#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>

namespace lenslab {

namespace {

thread_local std::optional<std::chrono::steady_clock::time_point> requestStart;

std::string utcTimestamp() {
    const auto now = std::chrono::system_clock::now();
    const std::time_t seconds = std::chrono::system_clock::to_time_t(now);
    const auto millis = std::chrono::duration_cast<std::chrono::milliseconds>(now.time_since_epoch()).count() % 1000;
    std::tm utc{};
    gmtime_r(&seconds, &utc);
    char text[64];
    std::snprintf(text, sizeof text, "%04d-%02d-%02dT%02d:%02d:%02d.%03dZ", utc.tm_year + 1900, utc.tm_mon + 1,
                  utc.tm_mday, utc.tm_hour, utc.tm_min, utc.tm_sec, static_cast<int>(millis));
    return text;
}

}  // namespace

AccessLog::AccessLog(const std::string& path)
    : out_(path.empty() ? stdout : std::fopen(path.c_str(), "a")), ownsFile_(!path.empty()) {
    if (!out_) throw std::runtime_error("cannot open the access log " + path);
}

AccessLog::~AccessLog() {
    if (ownsFile_) std::fclose(out_);
}

void AccessLog::requestStarted() { requestStart = std::chrono::steady_clock::now(); }

void AccessLog::requestFinished(const httplib::Request& req, const httplib::Response& res) {
    nlohmann::json entry = {{"time", utcTimestamp()},
                            {"remote", req.remote_addr},
                            {"method", req.method},
                            {"path", req.path},
                            {"status", res.status},
                            // a file or stream sent by a content provider has no body, only its length
                            {"bytes", res.content_provider_ ? res.content_length_ : res.body.size()}};
    if (requestStart) {
        entry["ms"] = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - *requestStart).count();
        requestStart.reset();
    }
    const std::string line = entry.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
    std::lock_guard<std::mutex> lock(mutex_);
    std::fwrite(line.data(), 1, line.size(), out_);
    std::fflush(out_);
}

}  // namespace lenslab
