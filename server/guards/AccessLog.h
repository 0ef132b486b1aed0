#pragma once
// The structured access log: one JSON object per request and line (time, client, method, path,
// status, response bytes, milliseconds), to a file or standard output.
#include <httplib.h>

#include <cstdio>
#include <mutex>
#include <string>

namespace lenslab {

class AccessLog {
public:
    explicit AccessLog(const std::string& path);  // empty: standard output
    ~AccessLog();
    AccessLog(const AccessLog&) = delete;
    AccessLog& operator=(const AccessLog&) = delete;

    // Called on the request's thread when routing begins and after the response is written.
    void requestStarted();
    void requestFinished(const httplib::Request& req, const httplib::Response& res);

private:
    std::FILE* out_;
    bool ownsFile_;
    std::mutex mutex_;
};

}  // namespace lenslab
