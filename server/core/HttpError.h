#pragma once
// A request the service refuses: the HTTP status and the message the client sees as {"error": ...}.
#include <stdexcept>
#include <string>

namespace lenslab {

class HttpError : public std::runtime_error {
public:
    HttpError(int status, const std::string& message) : std::runtime_error(message), status_(status) {}
    int status() const { return status_; }

private:
    int status_;
};

}  // namespace lenslab
