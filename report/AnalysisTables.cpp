#include "AnalysisTables.h"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "MarkupText.h"
#include "prescription/NumberText.h"

namespace lenslab {

namespace {

std::string exactNumber(double v) {
    if (!std::isfinite(v)) return "null";  // as designAnalysisJson writes it
    char b[40];
    std::snprintf(b, sizeof b, "%.17g", v);
    return b;
}

std::string path(std::initializer_list<std::string> parts) {
    std::string p;
    for (const std::string& part : parts) p += "/" + part;
    return p;
}
std::string index(std::size_t i) { return std::to_string(i); }

// A number with `decimals` after the point, of the value times scale.
ShownValue number(double v, const std::string& pointer, int decimals, double scale = 1) {
    return {formatFixed(v * scale, decimals), pointer, exactNumber(v), scale};
}
ShownValue word(const std::string& text, const std::string& pointer, const std::string& exact) { return {text, pointer, exact, 1}; }

// A field's value that exists only where the field is imaged: "not imaged" where no ray of the
// field reaches the image plane; NaN (a dash, null in the JSON) where it is imaged but unknown.
ShownValue fieldValue(const FieldAnalysis& f, double v, const std::string& pointer, int decimals) {
    return f.traced ? number(v, pointer, decimals) : word(kNotImaged, pointer, "null");
}
ShownValue label(const std::string& text) { return {text, "", "", 1}; }

std::string fieldPointer(std::size_t i, const std::string& rest) { return path({"fields", index(i)}) + rest; }

std::string attributes(const ShownValue& v) {
    std::string out;
    for (const auto& [name, value] : shownValueAttributes(v)) out += " " + name + "=\"" + escapeMarkup(value) + "\"";
    return out;
}

}  // namespace

ShownValue spotRmsShown(const LensDesignAnalysis& a, std::size_t field, std::size_t wavelength) {
    const std::string spot = fieldPointer(field, path({"spots", index(wavelength)}));
    const SpotDiagram& s = a.fields[field].spots[wavelength];
    return s.points.empty() ? word("blocked", spot + "/rays_passed", "0") : number(s.statistics.rmsRadius, spot + "/rms_radius_mm", 2, kUm);
}

std::vector<std::pair<std::string, std::string>> shownValueAttributes(const ShownValue& v) {
    if (v.pointer.empty()) return {};
    std::vector<std::pair<std::string, std::string>> out{{"data-json", v.pointer}, {"data-value", v.exact}};
    if (v.scale != 1) out.emplace_back("data-scale", exactNumber(v.scale));
    return out;
}

std::vector<AnalysisSetting> analysisSettings(const LensDesignAnalysis& a) {
    const bool infinity = a.lens.focus.infinity;
    const double focus = a.lens.focus.objectZ - a.lens.lens.frontZ();
    std::vector<AnalysisSetting> s{
        {"f-number", {"f/" + formatFNumber(a.lens.fstop), "/fstop", exactNumber(a.lens.fstop), 1}, ""},
        {"focus", infinity ? word("infinity", "/focus_distance", "null") : number(focus, "/focus_distance", 1), infinity ? "" : "mm"},
        {"image plane", word(imagePlaneName(a.imagePlane), "/image_plane", imagePlaneName(a.imagePlane)), ""},
        {"image plane z", number(a.imageZ, "/image_z", 4), "mm"},
        {"paraxial image z", number(a.planes.paraxialZ, "/image_planes/paraxial_z", 4), "mm"},
        {"film z", number(a.planes.filmZ, "/image_planes/film_z", 4), "mm"},
        {"best image z", number(a.planes.bestZ, "/image_planes/best_z", 4), "mm"},
        {"spot radii about",
         word(a.reference == SpotReference::ChiefRay ? "the chief ray" : "the centroid", "/reference", spotReferenceName(a.reference)), ""},
        {"primary wavelength", number(a.primaryWavelength, "/primary_wavelength_nm", 2), "nm"},
        {"largest field",
         a.largestFieldDegrees ? number(*a.largestFieldDegrees, "/largest_field_deg", 2) : word("none", "/largest_field_deg", "null"),
         a.largestFieldDegrees ? "\u00b0" : ""},
        {"largest field from", word(a.largestFieldSource, "/largest_field_source", a.largestFieldSource), ""},
        {"central obscuration",
         a.obscuration > 0 ? number(a.obscuration, "/obscuration", 3) : word("none", "/obscuration", exactNumber(a.obscuration)),
         a.obscuration > 0 ? "of the pupil radius" : ""},
    };
    if (!a.frequencies.empty() && !a.fields.empty())
        s.push_back({"MTF to",
                     number(a.frequencies.back(), path({"fields", "0", "mtf", "frequencies_lpmm", index(a.frequencies.size() - 1)}), 1),
                     "lp/mm"});
    return s;
}

std::vector<AnalysisTable> analysisTables(const LensDesignAnalysis& a, bool curves) {
    const bool chief = a.reference == SpotReference::ChiefRay;
    AnalysisTable spots{"spots",
                        std::string("Spot radii per field and wavelength, about ") + (chief ? "the chief ray" : "the centroid") +
                            " on the image plane; transmission is the share of the pupil whose rays arrive",
                        {"field (\u00b0)", "wavelength (nm)", "RMS radius (\u00b5m)", "geometric radius (\u00b5m)", "transmission",
                         "RMS wavefront (waves)"},
                        {}};
    for (std::size_t i = 0; i < a.fields.size(); ++i) {
        const FieldAnalysis& f = a.fields[i];
        const ShownValue field = number(f.fieldDegrees, fieldPointer(i, "/field_deg"), 2);
        for (std::size_t j = 0; j < f.spots.size(); ++j) {
            const std::string spot = fieldPointer(i, path({"spots", index(j)}));
            const SpotDiagram& s = f.spots[j];
            const bool blocked = s.points.empty();
            spots.rows.push_back(
                {field, number(s.wavelength, spot + "/wavelength_nm", 1), spotRmsShown(a, i, j),
                 blocked ? word("blocked", spot + "/rays_passed", "0") : number(s.statistics.geometricRadius, spot + "/geo_radius_mm", 2, kUm),
                 number(s.transmission, spot + "/transmission", 3),
                 number(f.rmsWavefrontWaves[j], fieldPointer(i, path({"rms_wavefront_waves", index(j)})), 3)});
        }
        if (f.traced)
            spots.rows.push_back({field, label("polychromatic"),
                                  number(f.polychromatic.rmsRadius, fieldPointer(i, "/polychromatic/rms_radius_mm"), 2, kUm),
                                  number(f.polychromatic.geometricRadius, fieldPointer(i, "/polychromatic/geo_radius_mm"), 2, kUm)});
        else
            spots.rows.push_back({field, label("polychromatic"), word(kNotImagedWhy, fieldPointer(i, "/traced"), "false")});
    }

    AnalysisTable fields{"fields", "Per field: the chief ray's image height on the image plane, its distortion", {"field (\u00b0)", "image height (mm)", "distortion (%)"}, {}};
    if (curves) {
        fields.caption += " and the relative illumination there";
        fields.columns.push_back("relative illumination");
    }
    for (std::size_t i = 0; i < a.fields.size(); ++i) {
        const FieldAnalysis& f = a.fields[i];
        const double height = f.chiefImage ? std::hypot(f.chiefImage->x, f.chiefImage->y) : NAN;
        std::vector<ShownValue> row{number(f.fieldDegrees, fieldPointer(i, "/field_deg"), 2),
                                    fieldValue(f, height, fieldPointer(i, "/image_height_mm"), 4),
                                    fieldValue(f, f.distortionPercent.value_or(NAN), fieldPointer(i, "/distortion_percent"), 3)};
        if (curves) row.push_back(fieldValue(f, f.relativeIllumination.value_or(NAN), fieldPointer(i, "/relative_illumination"), 3));
        fields.rows.push_back(row);
    }

    AnalysisTable shift{"focal-shift", "Chromatic focal shift: the paraxial focus from the d line's (mm, + toward the lens)",
                        {"wavelength (nm)", "focus shift (mm)"}, {}};
    for (std::size_t j = 0; j < a.focalShift.size(); ++j)
        shift.rows.push_back({number(a.focalShift[j].wavelength, path({"wavelengths_nm", index(j)}), 1),
                              number(a.focalShift[j].shift, path({"chromatic_focal_shift_mm", index(j)}), 5)});
    return {spots, fields, shift};
}


std::string analysisSettingsText(const LensDesignAnalysis& a) {
    std::string out;
    for (const AnalysisSetting& s : analysisSettings(a))
        out += (out.empty() ? "" : "; ") + s.name + ": " + s.value.text + (s.unit.empty() || s.unit == "\u00b0" ? "" : " ") + s.unit;
    return out + " (docs/analysis.md defines each number)";
}

std::string analysisSettingsHtml(const LensDesignAnalysis& a) {
    std::ostringstream out;
    out << "<dl class=\"analysis-settings\">\n";
    for (const AnalysisSetting& s : analysisSettings(a))
        out << "<div><dt>" << escapeMarkup(s.name) << "</dt><dd><span" << attributes(s.value) << ">" << escapeMarkup(s.value.text)
            << "</span>" << (s.unit.empty() || s.unit == "\u00b0" ? "" : " ") << escapeMarkup(s.unit) << "</dd></div>\n";
    out << "</dl>\n";
    return out.str();
}

std::string analysisTablesHtml(const LensDesignAnalysis& a, bool curves) {
    std::ostringstream out;
    for (const AnalysisTable& t : analysisTables(a, curves)) {
        out << "<table class=\"analysis-numbers\" data-table=\"" << t.name << "\">\n<caption>" << escapeMarkup(t.caption)
            << "</caption>\n<thead><tr>";
        for (const std::string& c : t.columns) out << "<th scope=\"col\">" << escapeMarkup(c) << "</th>";
        out << "</tr></thead>\n<tbody>\n";
        for (const auto& row : t.rows) {
            out << "<tr>";
            for (const ShownValue& v : row) out << "<td" << attributes(v) << ">" << escapeMarkup(v.text) << "</td>";
            out << "</tr>\n";
        }
        out << "</tbody>\n</table>\n";
    }
    return out.str();
}

std::string analysisTablesText(const LensDesignAnalysis& a, bool curves) {
    std::ostringstream out;
    for (const AnalysisTable& t : analysisTables(a, curves)) {
        out << t.caption << "\n";
        std::string line;
        for (const std::string& c : t.columns) line += (line.empty() ? "" : "  ") + c;
        out << line << "\n";
        for (const auto& row : t.rows) {
            line.clear();
            for (const ShownValue& v : row) line += (line.empty() ? "" : "  ") + v.text;
            out << line << "\n";
        }
    }
    return out.str();
}

}  // namespace lenslab
