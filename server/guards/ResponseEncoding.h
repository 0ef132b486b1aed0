#pragma once
// Which compression a response gets. cpp-httplib picks Brotli whenever a client accepts it, at
// Brotli's highest quality (11), which compresses about 1 MB/s: 220 ms for the editor's 225 KB
// preview answer, three times the preview's own work. gzip (zlib's default level) takes about
// 2 ms for 11% more bytes. So the service offers gzip to every client that accepts it.
#include <httplib.h>

namespace lenslab {

// Removes "br" and the codings the client refuses ("gzip;q=0") from the request's Accept-Encoding,
// which cpp-httplib reads when it compresses the answer. Called on the request before routing; the Request object is cpp-httplib's own mutable
// one, handed to the handlers as const.
void declineBrotli(const httplib::Request& req);

}  // namespace lenslab
