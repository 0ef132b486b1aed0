#pragma once
// A request's JSON body, read the one way every route reads it: anything nlohmann cannot make a
// value of (malformed text, a number past a double's range such as 1e400) is HttpError 400 naming
// `what` ("the render request", "the body"), never an exception a route lets through as a 500.
#include <httplib.h>
#include <nlohmann/json.hpp>

#include <string>

namespace lenslab {

nlohmann::json parseJsonBody(const httplib::Request& req, const std::string& what);

}  // namespace lenslab
