#pragma once
// Headers on every answer that keep the page and the API from being turned against their users.
// The policy allows what web/ loads and nothing more: its own module scripts and style sheet (no
// inline script or style attribute; styles set from scripts through the CSSOM need no
// 'unsafe-inline'), images from the service, data: (the editor's diagram, the favicon) and blob:
// (object URLs of fetched diagrams), fetch and EventSource to the same origin; no frames around it.
#include <utility>
#include <vector>

namespace lenslab {

inline const std::vector<std::pair<const char*, const char*>>& securityHeaders() {
    static const std::vector<std::pair<const char*, const char*>> headers = {
        {"X-Content-Type-Options", "nosniff"},
        {"Content-Security-Policy",
         "default-src 'self'; script-src 'self'; style-src 'self'; img-src 'self' data: blob:; connect-src 'self'; "
         "object-src 'none'; base-uri 'none'; form-action 'self'; frame-ancestors 'none'"},
        {"X-Frame-Options", "DENY"},
        {"Referrer-Policy", "no-referrer"}};
    return headers;
}

}  // namespace lenslab
