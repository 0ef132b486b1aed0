// GET /api/lenses/{id}/analysis: the lens designer's analysis (the `lenslab analyze --json` object)
// at fstop and focus, for wavelengths, fields, image plane and reference given as the command line
// takes them; with views=html also what the page shows of it (AnalysisViews.h); and GET
// /api/lenses/{id}/ghosts: its ghost analysis (`lenslab analyze --ghosts --json`) at fstop and
// focus. The inputs are checked first (at most 16 fields and 16 wavelengths; a malformed or
// out-of-range list is 400 naming its parameter); the analyses run in the heavy-work pool and are
// cached by the lens's content, the glass catalogs and the inputs; settings the lens cannot take are optics' 422 as
// elsewhere.
#include "AnalysisInputsText.h"
#include "AnalysisJson.h"
#include "AnalysisViews.h"
#include "GhostFormats.h"
#include "core/HttpError.h"
#include "core/HttpReply.h"
#include "prescription/OpticsError.h"
#include "core/QueryParameters.h"
#include "routes/ServiceParts.h"

namespace lenslab {

namespace {

using nlohmann::json;

DesignAnalysisInputs analysisInputs(const httplib::Request& req) {
    DesignAnalysisInputs in;
    in.lens = queryLensSettings(req);
    in.wavelengthsSource = "query parameter wavelengths";
    in.fieldsSource = "query parameter fields";
    in.maxFrequencySource = "query parameter max_frequency";
    try {
        if (const auto text = queryText(req, "wavelengths")) in.wavelengths = parseWavelengthList(*text, in.wavelengthsSource);
        if (const auto text = queryText(req, "fields")) {
            const FieldList fields = parseFieldList(*text, in.fieldsSource);
            in.fields = fields.values;
            in.fieldsInDegrees = fields.degrees;
        }
        if (const auto max = queryNumber(req, "max_frequency", 0, 1e5)) in.maxFrequency = *max;
        if (const auto text = queryText(req, "image_plane")) in.imagePlane = parseImagePlaneInput(*text, "query parameter image_plane");
        if (const auto text = queryText(req, "reference")) in.reference = parseSpotReferenceInput(*text, "query parameter reference");
        checkDesignAnalysisInputs(in);
    } catch (const InputListError& e) {
        throw HttpError(400, e.what());
    } catch (const SettingError& e) {
        throw HttpError(400, e.what());
    }
    return in;
}

// What the analysis depends on besides the lens: the values the request can set (exact doubles).
std::string inputsKey(const DesignAnalysisInputs& in) {
    const auto value = [](const std::optional<Setting>& s) { return s ? json(s->value) : json(nullptr); };
    return json{value(in.lens.fstop), value(in.lens.focusDistance), value(in.lens.wavelength), in.wavelengths,
                in.fields, in.fieldsInDegrees, in.maxFrequency, static_cast<int>(in.imagePlane),
                static_cast<int>(in.reference)}
        .dump();
}

// A cached JSON object answered with the lens's own fields first (the cache is shared by every
// upload of the same table, so it holds none of them): `head`'s members spliced into it, unparsed.
void replyCachedObject(httplib::Response& res, const json& head, const std::string& cached) {
    const std::string text = head.dump(-1, ' ', false, json::error_handler_t::replace);
    res.status = 200;
    res.set_content(text.substr(0, text.size() - 1) + "," + cached.substr(1), "application/json");
}

}  // namespace

void addAnalysisRoutes(httplib::Server& server, ServiceParts& parts) {
    server.Get(R"(/api/lenses/([^/]+)/analysis)", [&parts](const httplib::Request& req, httplib::Response& res) {
        const auto lens = findLens(parts, req.matches[1]);
        const auto views = queryText(req, "views");
        if (views && *views != "html") throw HttpError(400, "query parameter views: html or absent");
        const DesignAnalysisInputs inputs = analysisInputs(req);
        // Cached without the lens's id and name: two uploads of one table share it.
        const std::string key = "analysis|" + lensContentKey(parts, *lens) + "|" + inputsKey(inputs) + (views ? "|views" : "");
        const auto analysis = parts.work.cachedOrComputed(parts.analyses, key, clientOf(req), [&] {
            const LensDesignAnalysis a = analyzeLensDesign(lens->system, inputs);
            json body = designAnalysisJson(a);
            if (views) body["views"] = analysisViewsJson(a);
            body.erase("name");
            return textBytes(body.dump(-1, ' ', false, json::error_handler_t::replace));
        });
        replyCachedObject(res, {{"id", lens->id}, {"name", lens->name}}, bytesText(*analysis));
    });
    server.Get(R"(/api/lenses/([^/]+)/ghosts)", [&parts](const httplib::Request& req, httplib::Response& res) {
        const auto lens = findLens(parts, req.matches[1]);
        LensSettings settings = queryLensSettings(req);
        settings.wavelength = Setting{kWavelengthD, "the d line"};
        // A 256-surface upload has 32,640 paths: in the pool and cached, as the analysis.
        DesignAnalysisInputs inputs;
        inputs.lens = settings;
        const auto ghosts = parts.work.cachedOrComputed(
            parts.analyses, "ghosts|" + lensContentKey(parts, *lens) + "|" + inputsKey(inputs), clientOf(req), [&] {
                return textBytes(ghostAnalysisJson(analyzeGhosts(analyzeLens(lens->system, settings)))
                                     .dump(-1, ' ', false, json::error_handler_t::replace));
            });
        replyCachedObject(res, {{"id", lens->id}}, bytesText(*ghosts));
    });
}

}  // namespace lenslab
