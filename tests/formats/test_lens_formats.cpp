// What `lenslab lens` prints and the API serves, for a thick singlet whose first order has a
// closed form (the lensmaker's equation with its thickness term): each number under its own name,
// in its own units and frame. The API and the command line share this code, so comparing the two
// cannot catch a field that shows the wrong number.
#include <gtest/gtest.h>

#include <cstdio>

#include "settings/LensAnalysis.h"
#include "LensJson.h"
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
