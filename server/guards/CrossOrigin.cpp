#include "guards/CrossOrigin.h"

#include "guards/AccessControl.h"

namespace lenslab {

bool allowListedOrigin(const httplib::Request& req, httplib::Response& res, const AccessPolicy& policy) {
    res.set_header("Vary", "Origin, Accept-Encoding");  // the answer depends on both (ResponseEncoding.h)
    const std::string origin = req.get_header_value("Origin");
    if (origin.empty() || !isListedOrigin(origin, policy)) return false;
    res.set_header("Access-Control-Allow-Origin", origin);
    res.set_header("Access-Control-Expose-Headers",
                   "Location, Retry-After, X-Image-Width, X-Image-Height, X-Image-Fstop, X-Image-Exposure");
    if (req.method != "OPTIONS" || !req.has_header("Access-Control-Request-Method")) return false;
    res.status = 204;
    res.set_header("Access-Control-Allow-Methods", "GET, HEAD, POST, DELETE");
    res.set_header("Access-Control-Allow-Headers", "Authorization, Content-Type");
    res.set_header("Access-Control-Max-Age", "600");
    return true;
}

}  // namespace lenslab
