#include "core/UploadedFile.h"

#include "core/HttpError.h"
#include "core/QueryParameters.h"

namespace lenslab {

UploadedFile uploadedFile(const httplib::Request& req, const std::string& defaultName) {
    UploadedFile upload{queryText(req, "name").value_or(defaultName), req.body};
    if (req.is_multipart_form_data()) {
        if (!req.has_file("file")) throw HttpError(400, "the multipart upload needs a field named 'file'");
        const auto file = req.get_file_value("file");
        upload.text = file.content;
        if (!file.filename.empty()) upload.name = file.filename;
    }
    return upload;
}

}  // namespace lenslab
