#include "PrescriptionJson.h"

#include <algorithm>
#include <cmath>

#include "FiniteOrNull.h"
#include "LineText.h"
#include "PrescriptionPartsJson.h"
#include "prescription/GlassCatalog.h"
#include "prescription/Wavelength.h"

namespace lenslab {

using nlohmann::json;

LensTable withGapAfterRows(LensTable table) {
    if (table.layout == TableLayout::GapAfter) return table;
    for (std::size_t i = 0; i < table.rows.size(); ++i)
        table.rows[i].gap = i + 1 < table.rows.size() ? table.rows[i + 1].gap : 0;
    table.layout = TableLayout::GapAfter;
    return table;
}

namespace {

json optionalJson(const std::optional<double>& v) { return v ? json(*v) : json(nullptr); }

json rowJson(const LensTableRow& r) {
    json row = {{"radius", r.radius},
                {"gap", r.gap},
                {"index", r.index},
                {"diameter", r.diameter},
                {"stop", r.stop},
                {"glass", r.glass},
                {"glass_catalog", r.glassCatalog},
                {"abbe", r.abbe},
                {"conic", r.conic},
                {"aspheric", r.aspheric},
                {"mirror", r.mirror},
                {"obscuration_diameter", r.obscurationDiameter},
                {"coating", r.coating},
                {"name", r.name},
                {"clear_aperture", r.clearShape ? apertureJson(*r.clearShape) : json(nullptr)},
                {"obscuration", r.obscurationShape ? apertureJson(*r.obscurationShape) : json(nullptr)},
                {"frame", r.frame ? frameJson(*r.frame) : json(nullptr)},
                {"coordinate_break", r.coordinateBreak},
                {"automatic_diameter", r.automaticDiameter}};
    addSurfaceFormJson(row, r.form);
    return row;
}

}  // namespace

json prescriptionJson(const LensTable& source) {
    const LensTable table = withGapAfterRows(source);
    json rows = json::array();
    for (const LensTableRow& r : table.rows) rows.push_back(rowJson(r));
    return {{"name", table.name},
            {"layout", layoutName(table.layout)},
            {"comments", table.comments},
            {"catalogs", table.catalogs},
            {"wavelengths_nm", table.wavelengths},
            {"wavelength_weights", table.wavelengthWeights},
            {"primary_wavelength_nm", table.primaryWavelength},
            {"fields", designFieldsJson(table.fields)},
            {"object_distance", finiteOrNull(table.objectDistance)},
            {"entrance_pupil_diameter", optionalJson(table.entrancePupilDiameter)},
            {"f_number", optionalJson(table.designFNumber)},
            {"object_numerical_aperture", optionalJson(table.objectNumericalAperture)},
            {"image_frame", table.imageFrame ? frameJson(*table.imageFrame) : json(nullptr)},
            {"rows", rows}};
}

namespace {

// A glass or catalog name, checked before anything looks it up (the search for the nearest names
// costs with its length).
std::string nameText(const JsonFields& in, const char* field, const char* what) {
    const std::string name = in.text(field);
    if (name.size() > kMaxGlassNameLength)
        in.fail(std::string("a ") + what + " name of " + std::to_string(name.size()) +
                " characters: catalog names have at most " + std::to_string(kMaxGlassNameLength));
    if (!name.empty())
        if (const auto problem = wordTextProblem(name)) in.fail(std::string("the ") + what + " name holds " + *problem);
    return name;
}

LensTableRow rowFromJson(const json& row, const std::string& name, int line) {
    const JsonFields in(row, name, line);
    LensTableRow r;
    r.line = line;
    r.radius = in.number("radius", 0);
    r.gap = in.number("gap", 0);
    r.index = in.number("index", 0);
    r.diameter = in.number("diameter", 0);
    r.stop = in.flag("stop");
    r.glass = nameText(in, "glass", "glass");
    r.glassCatalog = nameText(in, "glass_catalog", "catalog");
    r.abbe = in.number("abbe", 0);
    r.conic = in.number("conic", 0);
    r.mirror = in.flag("mirror");
    r.obscurationDiameter = in.number("obscuration_diameter", 0);
    r.coating = in.text("coating");
    if (r.coating.size() > 256) in.fail("coating must be at most 256 characters");
    r.name = in.text("name");
    if (r.name.size() > 256) in.fail("name must be at most 256 characters");
    if (const auto problem = lineTextProblem(r.name)) in.fail("name holds " + *problem);
    const std::vector<double> terms = in.numbers("aspheric", kAsphericTerms);
    std::copy(terms.begin(), terms.end(), r.aspheric.begin());
    r.form = surfaceFormFromJson(in);
    if (in.has("clear_aperture")) r.clearShape = apertureFromJson(in.object("clear_aperture"));
    if (in.has("obscuration")) r.obscurationShape = apertureFromJson(in.object("obscuration"));
    if (in.has("frame")) r.frame = frameFromJson(in.object("frame"));
    r.coordinateBreak = in.flag("coordinate_break");
    r.automaticDiameter = in.flag("automatic_diameter");
    // A coordinate break is no surface and an automatic clear aperture is derived when the lens is
    // built: neither has a diameter of its own. A shaped clear aperture's is the one its shape needs.
    if (r.coordinateBreak && !r.frame) in.fail("a coordinate break needs its frame (decentre and tilt)");
    if (r.coordinateBreak && r.diameter != 0) in.fail("a coordinate break has no surface: its diameter must be 0");
    if (r.automaticDiameter && (r.diameter != 0 || r.clearShape))
        in.fail("an automatic clear aperture has diameter 0 and no clear_aperture");
    if (!r.coordinateBreak && !r.automaticDiameter && !(r.diameter > 0)) in.fail("diameter must be positive");
    if (r.clearShape && r.diameter != 2 * r.clearShape->reach())
        in.fail("diameter must be " + json(2 * r.clearShape->reach()).dump() +
                " mm, what the clear aperture's shape reaches (change the shape to change it)");
    if (r.index != 0 && r.index < 1) in.fail("index " + json(r.index).dump() + " is below 1 (0 or 1 for air)");
    if (r.abbe < 0) in.fail("Abbe number must not be negative");
    if (r.obscurationDiameter < 0 || (r.obscurationDiameter > 0 && r.diameter > 0 && r.obscurationDiameter >= r.diameter))
        in.fail("the obscuration must be smaller than the clear diameter");
    return r;
}

// The free text and names of the whole lens, checked as the readers of files would: bounded, on one
// line, wavelengths lenslab traces.
void checkHeader(const LensTable& table) {
    const auto fail = [&](const std::string& problem) { throw LensTableError(table.name, 0, problem); };
    std::size_t commentBytes = 0;
    for (std::size_t i = 0; i < table.comments.size(); ++i) {
        if (const auto problem = lineTextProblem(table.comments[i]))
            fail("comment " + std::to_string(i + 1) + " holds " + *problem);
        commentBytes += table.comments[i].size();
    }
    if (commentBytes > kMaxCommentBytes) fail("the comments are longer than " + std::to_string(kMaxCommentBytes) + " bytes");
    for (const std::string& catalog : table.catalogs) {
        if (catalog.size() > kMaxGlassNameLength) fail("a catalog name is at most " + std::to_string(kMaxGlassNameLength) + " characters");
        if (const auto problem = wordTextProblem(catalog)) fail("a catalog name holds " + *problem);
    }
    for (double nm : table.wavelengths)
        if (const auto problem = wavelengthProblem(nm)) fail("wavelengths_nm: " + *problem);
    if (const auto problem = wavelengthProblem(table.primaryWavelength)) fail("primary_wavelength_nm: " + *problem);
    if (table.wavelengthWeights.size() > table.wavelengths.size()) fail("more wavelength_weights than wavelengths_nm");
    for (double w : table.wavelengthWeights)
        if (w < 0) fail("wavelength_weights must not be negative");
    for (const auto& [what, value] : {std::pair{"entrance_pupil_diameter", table.entrancePupilDiameter},
                                      std::pair{"f_number", table.designFNumber},
                                      std::pair{"object_numerical_aperture", table.objectNumericalAperture}})
        if (value && !(*value > 0)) fail(std::string(what) + " must be positive (null: the lens gives none)");
}

}  // namespace

LensTable prescriptionFromJson(const json& body, const std::string& name) {
    if (!body.is_object() || !body.contains("rows") || !body.at("rows").is_array())
        throw LensTableError(name, 0, "the body needs \"rows\": a list of surfaces");
    const json& rows = body.at("rows");
    if (rows.empty()) throw LensTableError(name, 0, "the lens has no surfaces");
    if (rows.size() > std::size_t(kMaxLensSurfaces))
        throw LensTableError(name, 0, "too many surfaces: at most " + std::to_string(kMaxLensSurfaces));
    LensTable table;
    table.name = name;
    table.layout = TableLayout::GapAfter;
    table.format = "zmx";
    for (std::size_t i = 0; i < rows.size(); ++i) table.rows.push_back(rowFromJson(rows[i], name, int(i) + 1));
    const JsonFields in(body, name, 0);
    table.comments = in.texts("comments", 64);
    table.catalogs = in.texts("catalogs", 64);
    table.wavelengths = in.numbers("wavelengths_nm", 24);
    table.wavelengthWeights = in.numbers("wavelength_weights", 24);
    table.primaryWavelength = in.number("primary_wavelength_nm", kWavelengthD);
    if (in.has("fields")) table.fields = designFieldsFromJson(in.object("fields"));
    table.objectDistance = in.number("object_distance", table.objectDistance);
    table.entrancePupilDiameter = in.optionalNumber("entrance_pupil_diameter");
    table.designFNumber = in.optionalNumber("f_number");
    table.objectNumericalAperture = in.optionalNumber("object_numerical_aperture");
    if (in.has("image_frame")) table.imageFrame = frameFromJson(in.object("image_frame"));
    checkHeader(table);
    return table;
}

}  // namespace lenslab
