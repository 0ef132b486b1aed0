#pragma once
// A file uploaded to the service, as the upload routes take it: the multipart field "file" (its
// file name shown), or the request body as it is (`?name=` shown).
#include <httplib.h>

#include <string>

namespace lenslab {

struct UploadedFile {
    std::string name;  // as the client gave it; the stores make it a display name
    std::string text;
};

// HttpError 400 for a multipart body without a field "file".
UploadedFile uploadedFile(const httplib::Request& req, const std::string& defaultName);

}  // namespace lenslab
