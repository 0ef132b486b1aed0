// GET /api/renders/{id}/pixels: a finished render's linear RGB as float32 little-endian, row-major,
// top row first, decoded from its EXR, so that the page re-maps exposure itself without asking for a
// new image. The size and the f-number travel in headers; X-Image-Exposure is the report's
// normalisation 4N^2/pi (1 when the camera has no f-number).
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfStringAttribute.h>

#include <cmath>
#include <cstdlib>

#include "HttpError.h"
#include "Identifiers.h"
#include "ServiceParts.h"

namespace lenslab {

namespace {

static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__, "the floats are sent as the machine stores them");

struct LinearImage {
    int width = 0, height = 0;
    std::string body;  // float32 RGB triples
    double fstop = 0;  // 0: unknown
};

LinearImage readExr(const std::string& path) {
    Imf::InputFile file(path.c_str());
    const Imath::Box2i window = file.header().dataWindow();
    LinearImage image;
    image.width = window.max.x - window.min.x + 1;
    image.height = window.max.y - window.min.y + 1;
    image.body.resize(std::size_t(image.width) * image.height * 3 * sizeof(float));
    char* base = image.body.data();
    const std::size_t xStride = 3 * sizeof(float), yStride = xStride * image.width;
    // The frame buffer's origin is pixel (0, 0), which may lie outside the data window.
    char* origin = base - window.min.x * xStride - window.min.y * yStride;
    Imf::FrameBuffer fb;
    const char* names[] = {"R", "G", "B"};
    for (int c = 0; c < 3; ++c) fb.insert(names[c], Imf::Slice(Imf::FLOAT, origin + c * sizeof(float), xStride, yStride));
    file.setFrameBuffer(fb);
    file.readPixels(window.min.y, window.max.y);
    if (const auto* fstop = file.header().findTypedAttribute<Imf::StringAttribute>("lenslab.fstop")) {
        const double n = std::atof(fstop->value().c_str());
        if (std::isfinite(n) && n > 0) image.fstop = n;
    }
    return image;
}

}  // namespace

void addImageRoutes(httplib::Server& server, ServiceParts& parts) {
    server.Get(R"(/api/renders/([^/]+)/pixels)", [&parts](const httplib::Request& req, httplib::Response& res) {
        const std::string id = req.matches[1];
        if (!isSafeIdentifier(id)) throw HttpError(400, "'" + id.substr(0, 80) + "' is not a valid render id");
        const auto job = parts.jobs.find(id);
        if (!job) throw HttpError(404, "no render with id '" + id + "'");
        if (job->record.state != JobState::Done)
            throw HttpError(409, "render '" + id + "' is " + jobStateName(job->record.state) + ", not done");
        LinearImage image;
        try {
            image = readExr(parts.jobs.imagePath(id, "exr"));
        } catch (const std::exception& e) {
            throw HttpError(404, "the image of render '" + id + "' cannot be read: " + e.what());
        }
        res.status = 200;
        res.set_header("X-Image-Width", std::to_string(image.width));
        res.set_header("X-Image-Height", std::to_string(image.height));
        if (image.fstop > 0) res.set_header("X-Image-Fstop", std::to_string(image.fstop));
        res.set_header("X-Image-Exposure", std::to_string(image.fstop > 0 ? 4 * image.fstop * image.fstop / M_PI : 1.0));
        res.set_content(image.body, "application/octet-stream");
    });
}

}  // namespace lenslab
