// What `lenslab lens` prints and the API serves, for a thick singlet whose first order has a
// closed form (the lensmaker's equation with its thickness term): each number under its own name,
// in its own units and frame. The API and the command line share this code, so comparing the two
// cannot catch a field that shows the wrong number.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <vector>

#include "settings/LensAnalysis.h"
#include "LensJson.h"
#include "prescription/LensSystem.h"
#include "prescription/LensTable.h"
#include "LensText.h"

using namespace lenslab;

namespace {

// A stop 2 mm in front of a biconvex singlet: radii 50 and -200 mm, 4 mm thick, n 1.5, 20 mm wide.
const char* kSinglet = "0 0 0 6\n50 2 1.5 20\n-200 4 0 20\n";
constexpr double kStopGap = 2, kR1 = 50, kR2 = -200, kThickness = 4, kN = 1.5;

struct ClosedForm {
    double efl, back, front;
};

// Lensmaker: 1/f = (n-1) (1/R1 - 1/R2 + (n-1) d / (n R1 R2)); the glass's vertices lie f (n-1) d / (n R)
// inside the focal points on each side. The front vertex is the stop's, kStopGap further out.
ClosedForm singlet() {
    const double f = 1 / ((kN - 1) * (1 / kR1 - 1 / kR2 + (kN - 1) * kThickness / (kN * kR1 * kR2)));
    return {f, f * (1 - (kN - 1) * kThickness / (kN * kR1)), f * (1 + (kN - 1) * kThickness / (kN * kR2)) - kStopGap};
}

LensAnalysis analysis() { return analyzeLens(buildLensSystem(parseLensTable(kSinglet, "singlet")), std::nullopt, 1000); }

// The number on the text line that starts with `label`.
double textValue(const std::string& text, const std::string& label) {
    const std::size_t at = text.find("  " + label + " ");
    if (at == std::string::npos) throw std::runtime_error("no line " + label);
    double v = 0;
    if (std::sscanf(text.c_str() + at + 2 + label.size(), " %lf", &v) != 1) throw std::runtime_error("no number on " + label);
    return v;
}

}  // namespace

TEST(LensFormats, JsonFieldsHoldTheirOwnNumbers) {
    const ClosedForm expected = singlet();
    const nlohmann::json j = lensAnalysisJson(analysis());
    EXPECT_NEAR(j["efl"].get<double>(), expected.efl, 1e-6);
    EXPECT_NEAR(j["efl_front"].get<double>(), expected.efl, 1e-6);  // in air both sides' focal lengths agree
    EXPECT_NEAR(j["back_focal_distance"].get<double>(), expected.back, 1e-6);
    EXPECT_NEAR(j["front_focal_distance"].get<double>(), expected.front, 1e-6);
    EXPECT_DOUBLE_EQ(j["focus"]["distance"].get<double>(), 1000);  // from the front vertex, as asked
    ASSERT_EQ(j["surfaces"].size(), 3u);
    EXPECT_DOUBLE_EQ(j["surfaces"][1]["diameter"].get<double>(), 20);  // the table's diameter column
    EXPECT_DOUBLE_EQ(j["surfaces"][2]["z"].get<double>(), -(kStopGap + kThickness));
}

TEST(LensFormats, TextLinesHoldTheirOwnNumbers) {
    const ClosedForm expected = singlet();
    const std::string text = lensAnalysisText(analysis());
    EXPECT_NEAR(textValue(text, "effective focal length"), expected.efl, 1e-4);
    EXPECT_NEAR(textValue(text, "back focal distance"), expected.back, 1e-4);
    EXPECT_NEAR(textValue(text, "front focal distance"), expected.front, 1e-4);
    EXPECT_NEAR(textValue(text, "object distance"), 1000, 1e-4);
}

// Edges crossing inside their stated apertures: the lens reads, and the warning (line, message)
// reaches the JSON and the text.
TEST(LensFormats, WarningsReachTheJsonAndTheText) {
    const LensSystem lens = buildLensSystem(parseLensTable("50 0 1.5 20\n-20 1 1 20\n0 5 0 10\n", "edge.dat"));
    const LensAnalysis a = describeLens(lens, LensSettings{});
    const nlohmann::json j = lensAnalysisJson(a);
    ASSERT_EQ(j["warnings"].size(), 1u);
    EXPECT_EQ(j["warnings"][0]["line"].get<int>(), 2);
    EXPECT_NE(j["warnings"][0]["message"].get<std::string>().find("cross at height"), std::string::npos);
    EXPECT_NE(lensAnalysisText(a).find("warning (line 2): surfaces on lines 1 and 2 cross"), std::string::npos);
    EXPECT_TRUE(lensAnalysisJson(analysis())["warnings"].empty());
}

// A plate between flats has no focal points: described as afocal, its prescription still listed.
TEST(LensFormats, AnAfocalLensIsDescribedNotRefused) {
    const LensSystem plate = buildLensSystem(parseLensTable("rdm\nso 0 1e10\ns 0 5 1.5,60\nsto\ns 0 10\nepd 4; wl 587.56\n", "plate.seq"));
    const nlohmann::json j = lensAnalysisJson(describeLens(plate, LensSettings{}));
    EXPECT_TRUE(j["afocal"].get<bool>());
    EXPECT_TRUE(j["efl"].is_null());
    EXPECT_EQ(j["format"], "seq");
    ASSERT_EQ(j["surfaces"].size(), 2u);
    EXPECT_FALSE(j.contains("incomplete"));
    EXPECT_FALSE(lensAnalysisJson(analysis())["afocal"].get<bool>());
}

// A tilted, decentred surface (Code V DAR) and the file's own fields and wavelength weights, under
// new names; a centred surface has no frame.
TEST(LensFormats, FramesFieldsAndWeightsUnderTheirOwnNames) {
    const LensSystem lens = buildLensSystem(parseLensTable(
        "rdm\nso 0 1e10\ns 40 5 1.6,40\nsto\ns -60 10\ns 0 20\nyde 0.5; ade 3; dar\n"
        "epd 10; wl 656.27 587.56 486.13; ref 2; wtw 1 2 1; yan 0 10 20; wtf 1 1 0.5\n", "tilt.seq"));
    const nlohmann::json j = lensAnalysisJson(describeLens(lens, LensSettings{}));
    EXPECT_FALSE(j["rotationally_symmetric"].get<bool>());
    EXPECT_FALSE(j["surfaces"][0].contains("frame"));
    const nlohmann::json& frame = j["surfaces"][2]["frame"];
    EXPECT_DOUBLE_EQ(frame["decentre"][1].get<double>(), 0.5);
    EXPECT_DOUBLE_EQ(frame["tilt_degrees"][0].get<double>(), 3);
    EXPECT_EQ(frame["mode"], "decentre and return");
    const nlohmann::json& design = j["design"];
    EXPECT_EQ(design["wavelengths_nm"], nlohmann::json({656.27, 587.56, 486.13}));
    EXPECT_EQ(design["wavelength_weights"], nlohmann::json({1.0, 2.0, 1.0}));
    EXPECT_DOUBLE_EQ(j["primary_wavelength_nm"].get<double>(), 587.56);
    EXPECT_EQ(design["fields"]["type"], "object angle");
    ASSERT_EQ(design["fields"]["points"].size(), 3u);
    EXPECT_DOUBLE_EQ(design["fields"]["points"][2]["y"].get<double>(), 20);
    EXPECT_DOUBLE_EQ(design["fields"]["points"][2]["weight"].get<double>(), 0.5);
    EXPECT_DOUBLE_EQ(design["entrance_pupil_diameter"].get<double>(), 10);
}

// Issue 40, finding 6: the reflex lens (f/6.70 to f/13.08) listed full stops to f/64 and showed its
// range's narrow end rounded outward (f/13.1), and the API refused them. Every f-number a lens's
// data offers, in the JSON (its range's ends, its full stops) and in the text, is accepted by
// analyzeLens, the check behind the API, the renders and the command line.
TEST(LensFormats, EveryOfferedFNumberIsAccepted) {
    int lenses = 0;
    for (const auto& entry : std::filesystem::directory_iterator(LENSLAB_SOURCE_DIR "/lenses")) {
        if (!isLensFileName(entry.path().string())) continue;
        ++lenses;
        const std::string name = entry.path().filename().string();
        const LensSystem lens = loadLensSystem(entry.path().string());
        const LensAnalysis widest = analyzeLens(lens, LensSettings{});
        const nlohmann::json j = lensAnalysisJson(widest);
        const double fstopMin = j["fstop_min"], fstopMax = j["fstop_max"];
        std::vector<double> offered = {fstopMin, fstopMax};
        for (const auto& stop : j["full_stops"]) {
            EXPECT_GE(stop.get<double>(), fstopMin) << name;
            EXPECT_LE(stop.get<double>(), fstopMax) << name;
            offered.push_back(stop);
        }
        const std::string text = lensAnalysisText(widest);
        double shownMin = 0, shownMax = 0;
        ASSERT_EQ(std::sscanf(text.c_str() + text.find("(range f/"), "(range f/%lf to f/%lf)", &shownMin, &shownMax), 2) << name;
        offered.push_back(shownMin);
        offered.push_back(shownMax);
        for (const double fstop : offered) {
            LensSettings settings;
            settings.fstop = Setting{fstop, "fstop"};
            EXPECT_NO_THROW(analyzeLens(lens, settings)) << name << " at f/" << fstop;
        }
    }
    EXPECT_GE(lenses, 10);
    // The reflex lens's shadow closes the stop at f/13.08: offered to f/12.8, full stops to f/11.3.
    const LensSystem reflex = loadLensSystem(LENSLAB_SOURCE_DIR "/lenses/us4666259-ex1-reflex-500mm.zmx");
    const LensAnalysis widest = analyzeLens(reflex, LensSettings{});
    EXPECT_NEAR(widest.aperture.fstopMax, 13.0757, 1e-4);
    const nlohmann::json j = lensAnalysisJson(widest);
    EXPECT_EQ(j["fstop_max"], 12.8);
    EXPECT_EQ(j["full_stops"], nlohmann::json::array({8.0, 8 * std::sqrt(2.0)}));
    EXPECT_NE(lensAnalysisText(widest).find("(range f/6.71 to f/12.8)"), std::string::npos) << lensAnalysisText(widest);
}

