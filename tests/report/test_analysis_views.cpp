// What every view shows of an analysis (AnalysisTables.h, AnalysisPlots.h), against the analysis
// JSON the API answers: each shown value is the JSON's value at its pointer and its text that value
// rounded; one colour per wavelength in the spots, fans and field curvature, tangential solid and
// sagittal dashed; every text inside its plot; a blocked field said so in its plots and tables.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <regex>

#include <nlohmann/json.hpp>

#include "AnalysisJson.h"
#include "AnalysisPlots.h"
#include "AnalysisTables.h"
#include "HtmlCheck.h"
#include "prescription/LensSystem.h"

using namespace lenslab;

namespace {

const LensDesignAnalysis& dgaussAnalysis() {
    static const LensDesignAnalysis a = [] {
        DesignAnalysisInputs in;
        in.lens.fstop = Setting{4, "test"};
        in.lens.focusDistance = Setting{2000, "test"};
        return analyzeLensDesign(loadLensSystem(LENSLAB_SOURCE_DIR "/lenses/dgauss.50mm.dat"), in);
    }();
    return a;
}

const NamedSvg& plotNamed(const std::vector<NamedSvg>& plots, const std::string& name) {
    for (const NamedSvg& p : plots)
        if (p.name == name) return p;
    throw std::runtime_error("no plot " + name);
}

// The value at a JSON pointer against what a view says it shows there.
void expectShown(const nlohmann::json& analysis, const ShownValue& v) {
    SCOPED_TRACE(v.pointer + " shown as \"" + v.text + "\"");
    ASSERT_TRUE(analysis.contains(nlohmann::json::json_pointer(v.pointer)));
    const nlohmann::json& expected = analysis.at(nlohmann::json::json_pointer(v.pointer));
    if (expected.is_number()) {
        EXPECT_EQ(std::stod(v.exact), expected.get<double>());  // 17 digits: the same double
        std::smatch m;
        const std::string text = v.text;
        if (!std::regex_search(text, m, std::regex(R"(-?\d+(\.\d+)?$)"))) {
            EXPECT_EQ(expected.get<double>(), 0);  // "blocked", "none"
            return;
        }
        const std::string shown = m[0];
        const std::size_t dot = shown.find('.');
        const int decimals = dot == std::string::npos ? 0 : static_cast<int>(shown.size() - dot - 1);
        EXPECT_NEAR(std::stod(shown), expected.get<double>() * v.scale, 0.5 * std::pow(10.0, -decimals) + 1e-12);
    } else {
        EXPECT_EQ(v.exact, expected.is_string() ? expected.get<std::string>() : expected.dump());
    }
}

// (stroke colour, dash pattern) of every path in an SVG.
std::vector<std::pair<std::string, std::string>> strokes(const std::string& svg) {
    std::vector<std::pair<std::string, std::string>> out;
    const std::regex path(R"re(<path d="[^"]*" fill="none" stroke="(#[0-9a-f]{6})" stroke-width="2"( stroke-dasharray="[^"]*")?)re");
    for (std::sregex_iterator it(svg.begin(), svg.end(), path), end; it != end; ++it) out.emplace_back((*it)[1], (*it)[2]);
    return out;
}

}  // namespace

TEST(AnalysisViews, EveryShownValueIsTheJsonValueAtItsPointer) {
    const LensDesignAnalysis& a = dgaussAnalysis();
    const nlohmann::json json = designAnalysisJson(a);
    int shown = 0;
    for (const AnalysisSetting& s : analysisSettings(a)) {
        expectShown(json, s.value);
        ++shown;
    }
    for (const AnalysisTable& t : analysisTables(a))
        for (const auto& row : t.rows) {
            EXPECT_LE(row.size(), t.columns.size()) << t.name;
            for (const ShownValue& v : row)
                if (!v.pointer.empty()) {
                    expectShown(json, v);
                    ++shown;
                }
        }
    // 3 fields x 3 wavelengths x (field, wavelength, RMS, GEO, transmission, wavefront), 3 x 3
    // polychromatic, 3 x 4 per field, 3 x 2 focal shift, 13 settings.
    EXPECT_EQ(shown, 13 + 3 * 3 * 6 + 3 * 3 + 3 * 4 + 3 * 2);
    // The spot plot's legend names the same value, marked the same way.
    const std::string spot = plotNamed(designAnalysisPlots(a), "spot-field-2").svg;
    const ShownValue rms = spotRmsShown(a, 1, 2);
    EXPECT_NE(spot.find("data-json=\"/fields/1/spots/2/rms_radius_mm\" data-value=\"" + rms.exact + "\" data-scale=\"1000\">656.3 nm: RMS " +
                        rms.text + " \u00b5m</text>"),
              std::string::npos);
    EXPECT_TRUE(test::checkHtml(analysisSettingsHtml(a) + analysisTablesHtml(a)).errors.empty());
}

TEST(AnalysisViews, TheSettingsSayWhatIsUnsetInWords) {
    DesignAnalysisInputs in;
    in.fields = {0, 10};
    in.fieldsInDegrees = true;
    const LensDesignAnalysis a = analyzeLensDesign(loadLensSystem(LENSLAB_SOURCE_DIR "/lenses/ac254-100-a.dat"), in);
    ASSERT_FALSE(a.largestFieldDegrees);  // a doublet with its stop at the glass defines no field
    const nlohmann::json json = designAnalysisJson(a);
    std::map<std::string, ShownValue> byName;
    for (const AnalysisSetting& s : analysisSettings(a)) {
        expectShown(json, s.value);
        byName[s.name] = s.value;
    }
    EXPECT_EQ(byName["focus"].text, "infinity");
    EXPECT_EQ(byName["largest field"].text, "none");
    EXPECT_EQ(byName["largest field"].exact, "null");
    EXPECT_EQ(byName["central obscuration"].text, "none");
    EXPECT_NE(analysisSettingsText(a).find("largest field: none; largest field from: none"), std::string::npos) << analysisSettingsText(a);
}

TEST(AnalysisViews, OneColourPerWavelengthTangentialSolidSagittalDashed) {
    EXPECT_EQ(wavelengthColour(kWavelengthF), "#0072b2");
    EXPECT_EQ(wavelengthColour(kWavelengthD), "#009e73");
    EXPECT_EQ(wavelengthColour(kWavelengthC), "#d55e00");
    EXPECT_EQ(wavelengthColour(300), wavelengthColour(400));  // held beyond the ends
    EXPECT_NE(wavelengthColour(550), wavelengthColour(kWavelengthD));

    const LensDesignAnalysis& a = dgaussAnalysis();
    const std::vector<NamedSvg> plots = designAnalysisPlots(a);
    for (const char* name : {"fans-field-3", "field-curvature"}) {
        SCOPED_TRACE(name);
        const auto s = strokes(plotNamed(plots, name).svg);
        ASSERT_EQ(s.size(), 2 * a.wavelengths.size());
        for (std::size_t j = 0; j < a.wavelengths.size(); ++j) {
            EXPECT_EQ(s[2 * j].first, wavelengthColour(a.wavelengths[j]));
            EXPECT_EQ(s[2 * j].second, "");  // tangential: solid
            EXPECT_EQ(s[2 * j + 1].first, wavelengthColour(a.wavelengths[j]));
            EXPECT_EQ(s[2 * j + 1].second, " stroke-dasharray=\"6 4\"");  // sagittal: dashed
        }
    }
    const std::string spot = plotNamed(plots, "spot-field-3").svg;
    for (double w : a.wavelengths) EXPECT_NE(spot.find("fill=\"" + wavelengthColour(w) + "\"/>"), std::string::npos) << w;
    // The polychromatic MTF: the diffraction limit dotted grey, diffraction and geometric one colour
    // each, T solid and S dashed.
    const auto mtf = strokes(plotNamed(plots, "mtf-field-1").svg);
    ASSERT_EQ(mtf.size(), 5u);
    EXPECT_EQ(mtf[0].first, "#7f7f7f");
    EXPECT_NE(mtf[0].second.find("1.5 3"), std::string::npos);
    EXPECT_EQ(mtf[1].first, mtf[2].first);
    EXPECT_EQ(mtf[3].first, mtf[4].first);
    EXPECT_NE(mtf[1].first, mtf[3].first);
    for (double w : a.wavelengths) EXPECT_NE(mtf[1].first, wavelengthColour(w));
}

// Every text of every plot inside its picture (titles and labels at 12 px, 7.2 px a glyph), so that a
// legend or title never runs off a phone's screen.
TEST(AnalysisViews, EveryTextFitsItsPlot) {
    const LensDesignAnalysis& a = dgaussAnalysis();
    const std::regex svgSize(R"(viewBox="0 0 (\d+) [\d.]+")");
    const std::regex text(R"re(<text x="([\d.]+)"([^>]*)>([^<]*)</text>)re");
    for (const NamedSvg& plot : designAnalysisPlots(a)) {
        SCOPED_TRACE(plot.name);
        std::smatch size;
        ASSERT_TRUE(std::regex_search(plot.svg, size, svgSize));
        const double width = std::stod(size[1]);
        EXPECT_LE(width, 480);
        for (std::sregex_iterator it(plot.svg.begin(), plot.svg.end(), text), end; it != end; ++it) {
            const std::string label = (*it)[3], attributes = (*it)[2];
            std::size_t glyphs = 0;
            for (unsigned char c : label) glyphs += (c & 0xc0) != 0x80;  // UTF-8 characters
            const double x = std::stod((*it)[1]), w = 7.2 * glyphs;
            const double left = attributes.find("text-anchor=\"middle\"") != std::string::npos ? x - w / 2
                                : attributes.find("text-anchor=\"end\"") != std::string::npos  ? x - w
                                                                                               : x;
            EXPECT_GE(left, 0) << label;
            EXPECT_LE(left + w, width) << label;
        }
    }
}

TEST(AnalysisViews, ABlockedFieldSaysSo) {
    LensDesignAnalysis a = dgaussAnalysis();
    FieldAnalysis& f = a.fields[2];
    f.traced = false;
    for (SpotDiagram& s : f.spots) {
        s.points.clear();
        s.transmission = 0;
    }
    for (RayFan& fan : f.fans) std::fill(fan.tangential.begin(), fan.tangential.end(), NAN), std::fill(fan.sagittal.begin(), fan.sagittal.end(), NAN);
    const std::vector<NamedSvg> plots = designAnalysisPlots(a);
    for (const char* name : {"spot-field-3", "mtf-field-3", "fans-field-3"})
        EXPECT_NE(plotNamed(plots, name).svg.find("not imaged: no ray reaches the image plane"), std::string::npos) << name;
    EXPECT_EQ(plotNamed(plots, "spot-field-2").svg.find("not imaged"), std::string::npos);
    EXPECT_NE(plotNamed(plots, "spot-field-3").caption.find("This field is not imaged: no ray reaches the image plane."), std::string::npos);
    EXPECT_NE(analysisTablesHtml(a).find("<td data-json=\"/fields/2/traced\" data-value=\"false\">not imaged: no ray reaches the image plane</td>"),
              std::string::npos);
    EXPECT_NE(analysisTablesText(a).find("blocked  blocked  0.000"), std::string::npos) << analysisTablesText(a);
}

TEST(AnalysisViews, AFieldNoRayReachesIsNotImagedInTheJsonAndEveryTable) {
    // dgauss.50mm passes no ray at 60 degrees (issue 38: its image height, distortion and
    // illumination read 0, 0.000% and 1.000 in the tables, 0, 0 and 1 in the JSON).
    DesignAnalysisInputs in;
    in.fields = {20, 60};
    in.fieldsInDegrees = true;
    in.wavelengths = {kWavelengthD};
    const LensDesignAnalysis a = analyzeLensDesign(loadLensSystem(LENSLAB_SOURCE_DIR "/lenses/dgauss.50mm.dat"), in);
    const nlohmann::json json = designAnalysisJson(a);
    const nlohmann::json& blocked = json.at("fields").at(1);
    EXPECT_EQ(blocked.at("traced"), false);
    for (const char* key : {"image_height_mm", "chief_ray_image_mm", "distortion_percent", "relative_illumination"})
        EXPECT_TRUE(blocked.at(key).is_null()) << key << ": " << blocked.at(key);
    EXPECT_TRUE(json.at("distortion_percent").at(1).is_null());
    EXPECT_TRUE(json.at("relative_illumination").at(1).is_null());
    EXPECT_NEAR(json.at("fields").at(0).at("image_height_mm").get<double>(), 18.1378, 1e-4);

    // The command line's text, the page's and the report's HTML; each value the JSON's at its pointer.
    const std::string text = analysisTablesText(a);
    EXPECT_NE(text.find("\n20.00  18.1378  -1.074  0.295\n"), std::string::npos) << text;
    EXPECT_NE(text.find("\n60.00  not imaged  not imaged  not imaged\n"), std::string::npos) << text;
    const std::string html = analysisTablesHtml(a);
    for (const char* key : {"image_height_mm", "distortion_percent", "relative_illumination"})
        EXPECT_NE(html.find("<td data-json=\"/fields/1/" + std::string(key) + "\" data-value=\"null\">not imaged</td>"), std::string::npos)
            << key;
    for (const AnalysisTable& t : analysisTables(a))
        for (const auto& row : t.rows)
            for (const ShownValue& v : row)
                if (!v.pointer.empty()) expectShown(json, v);
}
