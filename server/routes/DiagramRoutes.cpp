// GET /api/lenses/{id}/diagram.png: the lens cross-section drawn on request (in the heavy-work pool)
// and cached by its parameters (lens and glass catalogs, mode, f-number, focus, wavelength, colour
// fans, field height, size).
#include <charconv>
#include <cstdio>
#include <optional>
#include <sstream>

#include "core/HttpError.h"
#include "core/HttpReply.h"
#include "LensDiagram.h"
#include "core/QueryParameters.h"
#include "routes/ServiceParts.h"

namespace lenslab {

namespace {

// The smallest size the diagram's layout (labels, margins) is drawn at.
const int kMinWidth = 320, kMaxWidth = 2400, kMinHeight = 200, kMaxHeight = 1600;

// Decimal digits only; nullopt for anything else, overflow included.
std::optional<int> pixels(const std::string& text) {
    int value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (text.empty() || error != std::errc() || end != text.data() + text.size()) return std::nullopt;
    return value;
}

// "W" (height W/2) or "WxH", in pixels.
std::pair<int, int> diagramSize(const httplib::Request& req) {
    const auto text = queryText(req, "size");
    if (!text) return {1200, 600};
    const std::size_t x = text->find('x');
    const auto width = pixels(text->substr(0, x));
    const auto height = x != std::string::npos ? pixels(text->substr(x + 1)) : width ? std::optional<int>(*width / 2) : std::nullopt;
    if (!width || !height) throw HttpError(400, "size must be WIDTH or WIDTHxHEIGHT in pixels");
    if (*width < kMinWidth || *width > kMaxWidth || *height < kMinHeight || *height > kMaxHeight)
        throw HttpError(400, "size must lie between " + std::to_string(kMinWidth) + "x" + std::to_string(kMinHeight) +
                                 " and " + std::to_string(kMaxWidth) + "x" + std::to_string(kMaxHeight));
    return {*width, *height};
}

DiagramOptions diagramOptions(const httplib::Request& req) {
    DiagramOptions o;
    try {
        o.mode = parseDiagramMode(queryText(req, "mode").value_or("exact"));
    } catch (const DiagramError& e) {
        throw HttpError(400, e.what());
    }
    o.lens = queryLensSettings(req);
    if (const auto colour = queryText(req, "colour")) {
        if (*colour != "0" && *colour != "1") throw HttpError(400, "colour must be 0 or 1");
        o.colourFans = *colour == "1";
    }
    o.fieldHeight = queryNumber(req, "field", 0, 100);
    std::tie(o.width, o.height) = diagramSize(req);
    return o;
}

std::string cacheKey(const std::string& lensId, const DiagramOptions& o) {
    std::ostringstream key;
    key.precision(17);
    key << lensId << "|" << static_cast<int>(o.mode) << "|" << (o.lens.fstop ? o.lens.fstop->value : 0.0) << "|"
        << (o.lens.focusDistance ? o.lens.focusDistance->value : std::numeric_limits<double>::infinity())
        << "|" << (o.fieldHeight ? *o.fieldHeight : -1.0) << "|" << o.width << "x" << o.height << "|"
        << (o.lens.wavelength ? o.lens.wavelength->value : 0.0) << "|" << o.colourFans;
    return key.str();
}

}  // namespace

void addDiagramRoutes(httplib::Server& server, ServiceParts& parts) {
    server.Get(R"(/api/lenses/([^/]+)/diagram\.png)", [&parts](const httplib::Request& req, httplib::Response& res) {
        const auto lens = findLens(parts, req.matches[1]);
        const DiagramOptions options = diagramOptions(req);
        const std::string key = cacheKey(lens->id + "|" + parts.glassCatalogs.digest(), options);
        const auto png = parts.work.cachedOrComputed(parts.diagrams, key, clientOf(req),
                                                     [&] { return drawLensDiagramPng(lens->system, options); });
        replyBytes(res, *png, "image/png");
        res.set_header("Cache-Control", "max-age=300");
    });
}

}  // namespace lenslab
