#pragma once
// CORS for the origins listed in --allow-origin: a page there may call the API with its token.
// Its answers carry Access-Control-Allow-Origin, and its browser's preflight (OPTIONS with
// Access-Control-Request-Method) is answered 204 before the token is asked for, since a browser
// never sends credentials with a preflight.
#include <httplib.h>

#include "core/ServiceConfig.h"

namespace lenslab {

// Adds the CORS headers to the answer when the request comes from a listed origin. True when the
// request is a preflight, now answered.
bool allowListedOrigin(const httplib::Request& req, httplib::Response& res, const AccessPolicy& policy);

}  // namespace lenslab
