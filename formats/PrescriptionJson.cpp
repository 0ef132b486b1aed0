#include "PrescriptionJson.h"

#include <cmath>

#include "LineText.h"
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

json prescriptionJson(const LensTable& source) {
    const LensTable table = withGapAfterRows(source);
    json rows = json::array();
    for (const LensTableRow& r : table.rows)
        rows.push_back({{"radius", r.radius}, {"gap", r.gap}, {"index", r.index}, {"diameter", r.diameter},
                        {"stop", r.stop}, {"glass", r.glass}, {"abbe", r.abbe}, {"conic", r.conic},
                        {"aspheric", r.aspheric}, {"mirror", r.mirror}, {"obscuration_diameter", r.obscurationDiameter},
                        {"coating", r.coating}});
    return {{"name", table.name},         {"comments", table.comments},
            {"catalogs", table.catalogs}, {"wavelengths_nm", table.wavelengths},
            {"primary_wavelength_nm", table.primaryWavelength}, {"rows", rows}};
}

namespace {

struct RowReader {
    const json& row;
    const std::string& name;
    int line;

    [[noreturn]] void fail(const std::string& problem) const { throw LensTableError(name, line, problem); }

    double number(const char* field, double fallback) const {
        if (!row.contains(field)) return fallback;
        const json& v = row.at(field);
        if (!v.is_number()) fail(std::string(field) + " must be a number");
        const double x = v.get<double>();
        if (!std::isfinite(x)) fail(std::string(field) + " is not a finite number");
        return x;
    }

    bool flag(const char* field) const {
        if (!row.contains(field)) return false;
        if (!row.at(field).is_boolean()) fail(std::string(field) + " must be true or false");
        return row.at(field).get<bool>();
    }

    std::string text(const char* field) const {
        if (!row.contains(field) || row.at(field).is_null()) return "";
        if (!row.at(field).is_string()) fail(std::string(field) + " must be a string");
        return row.at(field).get<std::string>();
    }
};

LensTableRow rowFromJson(const json& row, const std::string& name, int line) {
    RowReader in{row, name, line};
    if (!row.is_object()) in.fail("a row must be an object");
    LensTableRow r;
    r.line = line;
    r.radius = in.number("radius", 0);
    r.gap = in.number("gap", 0);
    r.index = in.number("index", 0);
    r.diameter = in.number("diameter", 0);
    r.stop = in.flag("stop");
    r.glass = in.text("glass");
    // Checked before anything looks the name up (the search for the nearest names costs with its length).
    if (r.glass.size() > kMaxGlassNameLength)
        in.fail("a glass name of " + std::to_string(r.glass.size()) + " characters: catalog names have at most " +
                std::to_string(kMaxGlassNameLength));
    if (!r.glass.empty())
        if (const auto problem = wordTextProblem(r.glass)) in.fail("the glass name holds " + *problem);
    r.abbe = in.number("abbe", 0);
    r.conic = in.number("conic", 0);
    r.mirror = in.flag("mirror");
    r.obscurationDiameter = in.number("obscuration_diameter", 0);
    r.coating = in.text("coating");
    if (r.coating.size() > 256) in.fail("coating must be at most 256 characters");
    if (row.contains("aspheric")) {
        const json& terms = row.at("aspheric");
        if (!terms.is_array() || terms.size() > kAsphericTerms)
            in.fail("aspheric must be a list of at most " + std::to_string(kAsphericTerms) + " numbers (r^2 .. r^16)");
        for (std::size_t i = 0; i < terms.size(); ++i) {
            if (!terms[i].is_number() || !std::isfinite(terms[i].get<double>()))
                in.fail("aspheric term " + std::to_string(i + 1) + " is not a finite number");
            r.aspheric[i] = terms[i].get<double>();
        }
    }
    if (!(r.diameter > 0)) in.fail("diameter must be positive");
    if (r.index != 0 && r.index < 1) in.fail("index " + json(r.index).dump() + " is below 1 (0 or 1 for air)");
    if (r.abbe < 0) in.fail("Abbe number must not be negative");
    if (r.obscurationDiameter < 0 || r.obscurationDiameter >= r.diameter)
        in.fail("the obscuration must be smaller than the clear diameter");
    return r;
}

// The free text and names of the whole lens, checked as the readers of files would: bounded, on one
// line, wavelengths lenslab traces.
void checkHeader(const LensTable& table) {
    const auto fail = [&](const std::string& problem) { throw LensTableError(table.name, 0, problem); };
    if (table.comments.size() > 64 || table.catalogs.size() > 64 || table.wavelengths.size() > 24)
        fail("at most 64 comments, 64 catalogs and 24 wavelengths");
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
    try {
        if (body.contains("comments")) table.comments = body.at("comments").get<std::vector<std::string>>();
        if (body.contains("catalogs")) table.catalogs = body.at("catalogs").get<std::vector<std::string>>();
        if (body.contains("wavelengths_nm")) table.wavelengths = body.at("wavelengths_nm").get<std::vector<double>>();
        if (body.contains("primary_wavelength_nm")) table.primaryWavelength = body.at("primary_wavelength_nm").get<double>();
    } catch (const json::exception&) {
        throw LensTableError(name, 0, "comments and catalogs must be lists of strings, wavelengths_nm a list of numbers");
    }
    checkHeader(table);
    return table;
}

}  // namespace lenslab
