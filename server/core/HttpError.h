#pragma once
// A request the service refuses: the HTTP status and the message the client sees as {"error": ...};
// for a refusal that passes (a busy server), the seconds to wait, sent as Retry-After.
#include <stdexcept>
#include <string>

namespace lenslab {

class HttpError : public std::runtime_error {
public:
    HttpError(int status, const std::string& message, int retryAfterSeconds = 0)
        : std::runtime_error(message), status_(status), retryAfterSeconds_(retryAfterSeconds) {}
    int status() const { return status_; }
    int retryAfterSeconds() const { return retryAfterSeconds_; }  // 0: none

private:
    int status_;
    int retryAfterSeconds_;
};

}  // namespace lenslab
