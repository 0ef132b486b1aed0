// The live prescription editor's routes. A prescription is edited as JSON rows (PrescriptionJson.h)
// and never stored until it is uploaded (POST /api/lenses):
//   GET  /api/lenses/{id}/prescription                 the stored lens's rows
//   GET  /api/lenses/{id}/table.dat, .../prescription.zmx, .seq   the stored lens written out
//   POST /api/prescriptions/preview                    rows in; lens JSON, diagram PNG, analysis out
//   POST /api/prescriptions/table.dat, .../prescription.zmx, .seq  rows in; the file text out
// A preview's work is bounded: its body (kMaxPreviewBody), its rows (kMaxLensSurfaces), a fixed
// analysis (3 fields, F d C; image_plane, reference and max_frequency as the analysis route takes them)
// and a fixed diagram size; it runs in the heavy-work pool, and its answer is cached by the body. A
// row's problem is 400 naming the row.
#include <cstdlib>
#include <functional>
#include <future>
#include <limits>
#include <sstream>

#include "AnalysisInputsText.h"
#include "AnalysisJson.h"
#include "AnalysisViews.h"
#include "CodeVWriter.h"
#include "core/Base64.h"
#include "core/ContentDigest.h"
#include "core/ContentDisposition.h"
#include "core/HttpError.h"
#include "core/HttpReply.h"
#include "core/JsonBody.h"
#include "LensDiagram.h"
#include "LensJson.h"
#include "LensTableWriter.h"
#include "PrescriptionJson.h"
#include "prescription/RowMedium.h"
#include "prescription/ZemaxFile.h"
#include "routes/ServiceParts.h"
#include "ZemaxWriter.h"

namespace lenslab {

namespace {

using nlohmann::json;

// A row with every field at full precision (a frame, two shaped apertures, 16 form terms, 8
// aspheric terms) is about 1.5 KiB of JSON: 256 of them about 380 KiB.
constexpr std::size_t kMaxPreviewBody = 512 * 1024;

const char* const kEditedLensName = "edited lens";

json parseBody(const httplib::Request& req) {
    if (req.body.size() > kMaxPreviewBody)
        throw HttpError(413, "a prescription body is at most " + std::to_string(kMaxPreviewBody / 1024) + " KiB");
    return parseJsonBody(req, "the body");
}

// A problem with one row: 400 {"error", "row" (1-based, absent for the whole lens), "problem"}.
void replyRowError(httplib::Response& res, const LensTableError& e) {
    json body = {{"problem", e.problem()}};
    if (e.line() > 0) {
        body["row"] = e.line();
        body["error"] = "row " + std::to_string(e.line()) + ": " + e.problem();
    } else {
        body["error"] = e.problem();
    }
    replyJson(res, 400, body);
}

std::optional<Setting> numberSetting(const json& body, const char* field, bool allowInfinity = false) {
    if (!body.contains(field) || body.at(field).is_null()) return std::nullopt;
    const json& v = body.at(field);
    if (allowInfinity && v.is_string() && (v == "inf" || v == "infinity"))
        return Setting{std::numeric_limits<double>::infinity(), std::string("field ") + field};
    if (!v.is_number()) throw HttpError(400, std::string(field) + " must be a number" + (allowInfinity ? " or \"inf\"" : ""));
    return Setting{v.get<double>(), std::string("field ") + field};
}

LensSettings bodyLensSettings(const json& body) {
    LensSettings s;
    s.fstop = numberSetting(body, "fstop");
    s.focusDistance = numberSetting(body, "focus", true);
    s.wavelength = numberSetting(body, "wavelength");
    return s;
}

DiagramOptions previewDiagramOptions(const json& body, const LensSettings& lens) {
    DiagramOptions o;
    o.lens = lens;
    o.width = 1000;
    o.height = 500;
    if (body.contains("mode")) {
        if (!body.at("mode").is_string()) throw HttpError(400, "mode must be exact, thick or overlay");
        try {
            o.mode = parseDiagramMode(body.at("mode").get<std::string>());
        } catch (const DiagramError& e) {
            throw HttpError(400, e.what());
        }
    }
    if (body.contains("colour")) {
        if (!body.at("colour").is_boolean()) throw HttpError(400, "colour must be true or false");
        o.colourFans = body.at("colour").get<bool>();
    }
    return o;
}

// The numbers and the page's views without the curves against field (the plots draw the points
// and fans: the JSON keeps the statistics).
json previewAnalysisJson(const LensDesignAnalysis& analysis) {
    json summary = designAnalysisJson(analysis);
    for (const char* unshown : {"ray_fans", "curves", "relative_illumination", "field_curvature"}) summary.erase(unshown);
    for (json& field : summary["fields"]) {
        field.erase("relative_illumination");  // interpolated from the two curve samples: too coarse to show
        for (json& spot : field["spots"]) spot.erase("points");
    }
    summary["views"] = analysisViewsJson(analysis, false);
    return summary;
}

// The analysis at the lens settings with the body's own choices, named as the API's query parameters.
DesignAnalysisInputs previewAnalysisInputs(const json& body, const LensSettings& settings) {
    DesignAnalysisInputs inputs;
    inputs.lens = settings;
    // The curves against field (relative illumination above all: 4/10 of the analysis at 16
    // samples) are not shown by the editor: their two end points keep it within the time of an edit.
    inputs.curveSamples = 2;
    const auto text = [&](const char* field) -> std::optional<std::string> {
        if (!body.contains(field) || body.at(field).is_null()) return std::nullopt;
        if (!body.at(field).is_string()) throw HttpError(400, std::string(field) + " must be a string");
        return body.at(field).get<std::string>();
    };
    try {
        if (const auto plane = text("image_plane")) inputs.imagePlane = parseImagePlaneInput(*plane, "field image_plane");
        if (const auto reference = text("reference")) inputs.reference = parseSpotReferenceInput(*reference, "field reference");
    } catch (const InputListError& e) {
        throw HttpError(400, e.what());
    }
    inputs.maxFrequencySource = "field max_frequency";
    if (const auto max = numberSetting(body, "max_frequency")) inputs.maxFrequency = max->value;
    return inputs;
}

// The preview's answer: the lens checked, analysed and drawn.
std::string previewJson(const LensTable& table, const DiagramOptions& drawing, const DesignAnalysisInputs& inputs) {
    const LensSystem system = buildLensSystem(table);
    const json lens = lensAnalysisJson(analyzeLens(system, drawing.lens));  // 422 here for settings it cannot take
    // The diagram draws while the analysis runs: the two are about equal and independent.
    auto diagram = std::async(std::launch::async, [&] { return drawLensDiagramPng(system, drawing); });
    json analysis;
    try {
        analysis = previewAnalysisJson(analyzeLensDesign(system, inputs));
    } catch (...) {
        diagram.wait();
        throw;
    }
    return json{{"lens", lens}, {"diagram_png_base64", base64Encode(diagram.get())}, {"analysis", analysis}}.dump(
        -1, ' ', false, json::error_handler_t::replace);
}

void preview(ServiceParts& parts, const httplib::Request& req, httplib::Response& res) {
    const json body = parseBody(req);
    try {
        // The body's checks before a place in the pool is taken.
        const LensTable table = prescriptionFromJson(body, kEditedLensName);
        const LensSettings settings = bodyLensSettings(body);
        const DiagramOptions drawing = previewDiagramOptions(body, settings);
        const DesignAnalysisInputs inputs = previewAnalysisInputs(body, settings);
        // The glass names in the body find the glasses of the catalogs held now.
        const std::string key = "preview|" + parts.glassCatalogs.digest() + "|" + contentDigest(req.body);
        const auto answer = parts.work.cachedOrComputed(parts.analyses, key, clientOf(req), [&] {
            const auto catalogsKept = parts.glassCatalogs.holdCatalogs();
            return textBytes(previewJson(table, drawing, inputs));
        });
        res.status = 200;
        res.set_content(reinterpret_cast<const char*>(answer->data()), answer->size(), "application/json");
    } catch (const LensTableError& e) {
        replyRowError(res, e);
    }
}

using TableWriter = std::string (*)(const LensTable&);

// A lens the chosen format cannot hold: 422 naming the row.
void replyUnwritable(httplib::Response& res, const LensTableError& e) {
    replyJson(res, 422, {{"error", e.what()}, {"row", e.line()}, {"problem", e.problem()}});
}

// The row a line of a written .zmx belongs to: its SURF n is row n (SURF 0 the object); 0 for the
// header and the image surface.
int zmxRowOfLine(const std::string& text, int line, std::size_t rows) {
    std::istringstream in(text);
    int surface = 0;
    std::string words;
    for (int at = 1; at <= line && std::getline(in, words); ++at)
        if (words.rfind("SURF ", 0) == 0) surface = std::atoi(words.c_str() + 5);
    return surface >= 1 && static_cast<std::size_t>(surface) <= rows ? surface : 0;
}

// Edited rows as a .zmx that reads back. A glass only the prescription itself defined (a Code V
// private glass, its rows carry its name alone) is written by name, which no catalog holds: such a
// lens is refused, naming the row, rather than written into a file that does not open.
std::string writeZemaxThatReadsBack(const LensTable& table) {
    std::string text = writeZemaxText(table);
    try {
        const LensTable readBack = parseZemax(text, table.name);
        std::vector<LensWarning> warnings;
        for (const LensTableRow& row : readBack.rows) rowMedium(readBack, row, warnings);  // its glasses, as a reader finds them
    } catch (const LensTableError& e) {
        throw LensTableError(table.name, zmxRowOfLine(text, e.line(), table.rows.size()),
                             "written to a .zmx, this lens would not read back: " + e.problem());
    }
    return text;
}

void replyTableText(httplib::Response& res, std::string text, const std::string& fileName) {
    res.set_content(std::move(text), "text/plain; charset=utf-8");
    res.set_header("Content-Disposition", attachmentDisposition(fileName));
}

void exportEdited(const httplib::Request& req, httplib::Response& res, TableWriter write, const std::string& fileName) {
    LensTable table;
    try {
        table = prescriptionFromJson(parseBody(req), kEditedLensName);
    } catch (const LensTableError& e) {
        return replyRowError(res, e);
    }
    try {
        replyTableText(res, write(withGapAfterRows(table)), fileName);
    } catch (const LensTableError& e) {
        replyUnwritable(res, e);
    }
}

// A stored lens's download is named as the page names the lens: its file's name (the bundled
// file's, the upload's) without the extension, else its title, else its id.
std::string downloadName(const StoredLens& lens, const char* extension) {
    const std::string stem = lensFileStem(lens.name);
    const std::string& name = !stem.empty() ? stem : !lens.description.empty() ? lens.description : lens.id;
    return name + extension;
}

// A stored lens written out (its rows as JSON, its .dat, its .zmx), read and written once per state
// of the lens and the glass catalogs, in the heavy-work pool, and cached: a 1 MB Code V upload read
// again per request took 611 MB for 32 readers.
std::shared_ptr<const Bytes> storedLensText(ServiceParts& parts, const httplib::Request& req, const StoredLens& lens,
                                            const std::string& format, const std::function<std::string(const LensTable&)>& write) {
    const std::string key = "stored-lens|" + format + "|" + lens.id + "|" + lens.name + "|" +
                            std::to_string(static_cast<int>(lens.system.layout)) + "|" + lensContentKey(parts, lens);
    return parts.work.cachedOrComputed(parts.analyses, key, clientOf(req), [&] {
        const auto catalogsKept = parts.glassCatalogs.holdCatalogs();
        return textBytes(write(storedTable(lens)));
    });
}

void replyStoredTable(ServiceParts& parts, const httplib::Request& req, httplib::Response& res, TableWriter write,
                      const char* extension) {
    const auto lens = findLens(parts, req.matches[1]);
    try {
        const auto text = storedLensText(parts, req, *lens, extension,
                                         [write](const LensTable& table) { return write(withGapAfterRows(table)); });
        replyTableText(res, bytesText(*text), downloadName(*lens, extension));
    } catch (const LensTableError& e) {
        replyUnwritable(res, e);
    }
}

}  // namespace

void addPrescriptionRoutes(httplib::Server& server, ServiceParts& parts) {
    server.Get(R"(/api/lenses/([^/]+)/prescription)", [&parts](const httplib::Request& req, httplib::Response& res) {
        const auto lens = findLens(parts, req.matches[1]);
        const auto text = storedLensText(parts, req, *lens, "rows", [&lens](const LensTable& table) {
            json body = prescriptionJson(table);
            body["id"] = lens->id;
            return jsonText(body);
        });
        replyBytes(res, *text, "application/json");
    });
    server.Get(R"(/api/lenses/([^/]+)/table\.dat)", [&parts](const httplib::Request& req, httplib::Response& res) {
        replyStoredTable(parts, req, res, writeLensTableText, ".dat");
    });
    server.Get(R"(/api/lenses/([^/]+)/prescription\.zmx)", [&parts](const httplib::Request& req, httplib::Response& res) {
        replyStoredTable(parts, req, res, writeZemaxText, ".zmx");
    });
    server.Get(R"(/api/lenses/([^/]+)/prescription\.seq)", [&parts](const httplib::Request& req, httplib::Response& res) {
        replyStoredTable(parts, req, res, writeCodeVText, ".seq");
    });
    server.Post("/api/prescriptions/preview",
                [&parts](const httplib::Request& req, httplib::Response& res) { preview(parts, req, res); });
    server.Post("/api/prescriptions/table.dat", [](const httplib::Request& req, httplib::Response& res) {
        exportEdited(req, res, writeLensTableText, "edited-lens.dat");
    });
    server.Post("/api/prescriptions/prescription.zmx", [](const httplib::Request& req, httplib::Response& res) {
        exportEdited(req, res, writeZemaxThatReadsBack, "edited-lens.zmx");
    });
    server.Post("/api/prescriptions/prescription.seq", [](const httplib::Request& req, httplib::Response& res) {
        exportEdited(req, res, writeCodeVText, "edited-lens.seq");
    });
}

}  // namespace lenslab
