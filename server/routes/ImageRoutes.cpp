// GET /api/renders/{id}/pixels: a finished render's linear RGB as float32 little-endian, row-major,
// top row first, decoded from its EXR, so that the page re-maps exposure itself without asking for a
// new image. The size and the f-number travel in headers; X-Image-Exposure is the report's
// normalisation 4N^2/pi (1 when the camera has no f-number).
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfStringAttribute.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <memory>
#include <vector>

#include "core/HttpError.h"
#include "core/Identifiers.h"
#include "routes/ServiceParts.h"

namespace lenslab {

namespace {

static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__, "the floats are sent as the machine stores them");

// An EXR opened for reading its pixels a band of rows at a time, so that sending a large image
// costs a band's memory, not the whole image's (16 concurrent 1920x1920 downloads took 1.2 GB).
class ExrRows {
public:
    explicit ExrRows(const std::string& path) : file_(path.c_str()), window_(file_.header().dataWindow()) {}

    int width() const { return window_.max.x - window_.min.x + 1; }
    int height() const { return window_.max.y - window_.min.y + 1; }
    std::size_t rowBytes() const { return std::size_t(width()) * 3 * sizeof(float); }
    double fstop() const {  // 0: unknown
        const auto* fstop = file_.header().findTypedAttribute<Imf::StringAttribute>("lenslab.fstop");
        const double n = fstop ? std::atof(fstop->value().c_str()) : 0;
        return std::isfinite(n) && n > 0 ? n : 0;
    }

    // Sends bytes from `offset` on, up to `length`, from the band of rows that holds `offset`.
    bool send(std::size_t offset, std::size_t length, httplib::DataSink& sink) {
        const int first = static_cast<int>(offset / rowBytes());
        const int last = std::min(height(), first + kBandRows) - 1;
        band_.resize(std::size_t(last - first + 1) * rowBytes());
        const std::size_t xStride = 3 * sizeof(float), yStride = rowBytes();
        // The frame buffer's origin is pixel (0, 0), which may lie outside the data window.
        char* origin = band_.data() - window_.min.x * xStride - std::ptrdiff_t(window_.min.y + first) * yStride;
        Imf::FrameBuffer fb;
        const char* names[] = {"R", "G", "B"};
        for (int c = 0; c < 3; ++c) fb.insert(names[c], Imf::Slice(Imf::FLOAT, origin + c * sizeof(float), xStride, yStride));
        file_.setFrameBuffer(fb);
        file_.readPixels(window_.min.y + first, window_.min.y + last);
        const std::size_t start = offset - std::size_t(first) * rowBytes();
        return sink.write(band_.data() + start, std::min(length, band_.size() - start));
    }

private:
    static constexpr int kBandRows = 16;
    Imf::InputFile file_;
    Imath::Box2i window_;
    std::vector<char> band_;
};

}  // namespace

void addImageRoutes(httplib::Server& server, ServiceParts& parts) {
    server.Get(R"(/api/renders/([^/]+)/pixels)", [&parts](const httplib::Request& req, httplib::Response& res) {
        const std::string id = req.matches[1];
        if (!isSafeIdentifier(id)) throw HttpError(400, "'" + id.substr(0, 80) + "' is not a valid render id");
        const auto job = parts.jobs.find(id);
        if (!job) throw HttpError(404, "no render with id '" + id + "'");
        if (job->record.state != JobState::Done)
            throw HttpError(409, "render '" + id + "' is " + jobStateName(job->record.state) + ", not done");
        auto slot = takeDownloadSlot(parts, req);
        std::shared_ptr<ExrRows> image;
        try {
            image = std::make_shared<ExrRows>(parts.jobs.imagePath(id, "exr"));
        } catch (const std::exception& e) {
            // OpenEXR's message names the file: it goes to the log only.
            std::cerr << "lenslab serve: " << e.what() << "\n";
            throw HttpError(404, "the image of render '" + id + "' cannot be read (missing or damaged)");
        }
        const double fstop = image->fstop();
        res.status = 200;
        res.set_header("X-Image-Width", std::to_string(image->width()));
        res.set_header("X-Image-Height", std::to_string(image->height()));
        if (fstop > 0) res.set_header("X-Image-Fstop", std::to_string(fstop));
        res.set_header("X-Image-Exposure", std::to_string(fstop > 0 ? 4 * fstop * fstop / M_PI : 1.0));
        res.set_content_provider(image->rowBytes() * image->height(), "application/octet-stream",
                                 [image, slot](std::size_t offset, std::size_t length, httplib::DataSink& sink) {
                                     try {
                                         return image->send(offset, length, sink);
                                     } catch (const std::exception& e) {  // damaged past its header
                                         std::cerr << "lenslab serve: " << e.what() << "\n";
                                         return false;
                                     }
                                 });
    });
}

}  // namespace lenslab
