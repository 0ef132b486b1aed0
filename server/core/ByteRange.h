#pragma once
// Byte ranges (Range: bytes=...), applied by the service instead of cpp-httplib 0.11.4, which cuts
// error answers and event streams too and answers a range past the end with an impossible
// Content-Range and no body. Here: one range of a complete 200 answer gives 206; a range that lies
// outside it gives 416 with "Content-Range: bytes */LENGTH" and a JSON error; several ranges, or a
// Range header that is not "bytes=", give the whole answer (RFC 9110 lets a server ignore them).
#include <httplib.h>

#include <string>

namespace lenslab {

// Called once the answer is complete (body or content provider with its length), before it is sent.
void applyByteRange(const std::string& rangeHeader, httplib::Response& res);

}  // namespace lenslab
