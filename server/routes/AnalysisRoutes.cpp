// GET /api/lenses/{id}/analysis: the lens designer's analysis (the `lenslab analyze --json` object)
// at fstop and focus, for wavelengths, fields, image plane and reference given as the command line
// takes them. The work is
// bounded by the inputs' check (at most 16 fields and 16 wavelengths); a malformed or out-of-range
// list is 400 naming its parameter, settings the lens cannot take are optics' 422 as elsewhere.
#include "AnalysisInputsText.h"
#include "AnalysisJson.h"
#include "core/HttpError.h"
#include "core/HttpReply.h"
#include "prescription/OpticsError.h"
#include "core/QueryParameters.h"
#include "routes/ServiceParts.h"

namespace lenslab {

namespace {

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

}  // namespace

void addAnalysisRoutes(httplib::Server& server, ServiceParts& parts) {
    server.Get(R"(/api/lenses/([^/]+)/analysis)", [&parts](const httplib::Request& req, httplib::Response& res) {
        const auto lens = findLens(parts, req.matches[1]);
        nlohmann::json body = designAnalysisJson(analyzeLensDesign(lens->system, analysisInputs(req)));
        body["id"] = lens->id;
        replyJson(res, 200, body);
    });
}

}  // namespace lenslab
