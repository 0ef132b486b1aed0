#pragma once
// A download's Content-Disposition for any file name a person gave (RFC 6266): the UTF-8 name in
// filename* (RFC 8187 percent-encoding), and an ASCII stand-in in the quoted filename for clients
// that read only that. A name is a name, never a path: slashes, backslashes and control characters
// become '_' in both, so no client is told to write into another folder.
#include <string>

namespace lenslab {

// `fileName` in UTF-8 (a stored lens's display name with its extension).
std::string attachmentDisposition(const std::string& fileName);

}  // namespace lenslab
