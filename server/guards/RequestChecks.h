#pragma once
// Checks on a request's head, made before its body is read or any route runs: framing that could
// be read two ways (request smuggling: two lengths, a coding other than chunked, two Host headers),
// a declared body past the limit (refused before "100 Continue"), compressed bodies (cpp-httplib would inflate them with no
// size limit), form-encoded bodies (cpp-httplib caps those at 8 KiB, far below the body limit),
// and Range headers asking for more ranges than allowed (each range is a copy of the resource).
#include <httplib.h>

#include <optional>

#include "core/HttpError.h"
#include "core/ServiceConfig.h"

namespace lenslab {

// The refusal for a request that must not go further, or nullopt.
std::optional<HttpError> refuseRequestHead(const httplib::Request& req, const HttpLimits& limits);

}  // namespace lenslab
