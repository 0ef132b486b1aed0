#pragma once
// The access check made on every request's head, before its body is read: cross-origin requests
// are refused unless their origin is allowed (a page on another site must not drive the API with
// the visitor's network position), and with a token set, requests that write or spend CPU (every
// method but GET, HEAD and OPTIONS, and the reads computed in the heavy-work pool: a lens's analysis
// and diagram; all reads when they are private) must carry it as "Authorization: Bearer TOKEN".
#include <httplib.h>

#include <optional>

#include "core/HttpError.h"
#include "core/ServiceConfig.h"

namespace lenslab {

// The refusal (401 or 403) for a request the policy does not let through, or nullopt.
std::optional<HttpError> refuseAccess(const httplib::Request& req, const AccessPolicy& policy);

// True for an origin listed in --allow-origin.
bool isListedOrigin(const std::string& origin, const AccessPolicy& policy);

// Reads the token from `path`, or writes a new random one there (mode 0600) when the file does not
// exist; `created` says which. std::runtime_error when the file cannot be read or written.
std::string loadOrCreateToken(const std::string& path, bool& created);

// True for addresses that only this host can reach (127.0.0.0/8, ::1, localhost).
bool isLoopbackHost(const std::string& host);

}  // namespace lenslab
