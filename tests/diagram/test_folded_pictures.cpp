// Folded systems drawn as they are laid out in space, read back as pixels: the beam, the mirrors and
// the film where the reflection law puts them, worked out here from Code V's tilt convention and a
// thick-lens focus, and no ray running straight on past a mirror as the unfolded drawing has it.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "DiagramStyle.h"
#include "DiagramTestSupport.h"
#include "prescription/CodeVFile.h"

namespace lenslab::test {
namespace {

using namespace diagram_style;

// The singlet in front of the folds: N 1.6, radii 100 and -150, 5 mm thick, stop on its front.
constexpr double kIndex = 1.6, kR1 = 100, kR2 = -150, kThickness = 5;
const std::string kSinglet = "rdm\nso 0 1e10\ns 100 5 1.6,40\nsto\ns -150 20\n";
const std::string kPupil = "si 0 0\nepd 20; wl 587.5618\n";

// The thick lens's back focal distance (from its rear vertex): power (n-1)(1/R1 - 1/R2) + (n-1)^2 t /
// (n R1 R2), and the rear principal plane t (n-1) / (n R1) of the focal length before the rear vertex.
double backFocalDistance() {
    const double power = (kIndex - 1) * (1 / kR1 - 1 / kR2) + (kIndex - 1) * (kIndex - 1) * kThickness / (kIndex * kR1 * kR2);
    return (1 - (kIndex - 1) * kThickness / (kIndex * kR1)) / power;
}

ZY plus(ZY a, double s, ZY d) { return {a.z + s * d.z, a.y + s * d.y}; }

// The axis through flat fold mirrors (Code V ADE alpha with BEN), in the drawing's (z, y): light
// arrives along -z. Code V's ADE turns a surface's axes about x by alpha, so in lens space (+z toward
// the scene) a frame turned by phi has its z axis at (cos phi, -sin phi); the mirror's normal is that
// of phi + alpha, the light leaves as reflected about it, and BEN turns the frame by alpha once more.
struct FoldedAxis {
    std::vector<ZY> mirrors;         // each mirror's vertex
    std::vector<ZY> arriving;        // the light's direction arriving at each mirror
    std::vector<ZY> mirrorLines;     // each mirror's direction in the section
    ZY focus, leaving;               // the focus and the light's direction toward it
};

FoldedAxis foldAxis(ZY firstMirror, const std::vector<double>& tilts, const std::vector<double>& legs, double toFocus) {
    FoldedAxis f;
    ZY at = firstMirror, d{-1, 0};
    double phi = 0;
    for (std::size_t k = 0; k < tilts.size(); ++k) {
        const double a = (phi + tilts[k]) * M_PI / 180;
        const ZY n{std::cos(a), -std::sin(a)};
        f.mirrors.push_back(at);
        f.arriving.push_back(d);
        f.mirrorLines.push_back({-n.y, n.z});
        const double along = d.z * n.z + d.y * n.y;
        d = {d.z - 2 * along * n.z, d.y - 2 * along * n.y};
        phi += 2 * tilts[k];
        at = plus(at, k + 1 < tilts.size() ? legs[k] : toFocus, d);
    }
    f.focus = at;
    f.leaving = d;
    return f;
}

// What the drawing misses of the folded path: ray ink at the middle of every leg after each mirror,
// none straight on past a mirror (12 mm on, past the beam's 8 mm half width), the mirror's ink 1.5 mm
// either side of its vertex along its line, and the film across the last leg at the focus (within
// 1.5 mm along the leg). Empty when the drawing shows it all.
std::vector<std::string> foldMisses(const LensSystem& lens, const FoldedAxis& fold) {
    DiagramOptions options;
    options.fieldHeight = 0.0;  // the axial fan only: the legs' ink is the axial beam's
    const DiagramPicture picture = layoutDiagram(lens, options);
    const RgbaImage image = renderDiagram(lens, options);
    auto at = [&](ZY p) { return picture.view.toPicture(p); };
    std::vector<std::string> misses;
    for (std::size_t k = 0; k < fold.mirrors.size(); ++k) {
        const ZY next = k + 1 < fold.mirrors.size() ? fold.mirrors[k + 1] : fold.focus;
        const ZY middle{0.5 * (fold.mirrors[k].z + next.z), 0.5 * (fold.mirrors[k].y + next.y)};
        if (!showsNear(image, at(middle), kExactRay, 0.35)) misses.push_back("no ray after mirror " + std::to_string(k + 1));
        if (showsNear(image, at(plus(fold.mirrors[k], 12, fold.arriving[k])), kExactRay, 0.2))
            misses.push_back("a ray straight on past mirror " + std::to_string(k + 1));
        for (double s : {-1.5, 1.5})
            if (!showsNear(image, at(plus(fold.mirrors[k], s, fold.mirrorLines[k])), kMirror, 0.5))
                misses.push_back("no mirror " + std::to_string(k + 1) + " at " + std::to_string(s) + " mm along it");
    }
    // The film runs across the last leg: two points 1.5 mm either side of the focus, each within
    // 1.5 mm of it along the leg.
    const ZY across{-fold.leaving.y, fold.leaving.z};
    for (double s : {-1.5, 1.5}) {
        bool found = false;
        for (double t = -1.5; t <= 1.5 && !found; t += 0.05) found = showsNear(image, at(plus(plus(fold.focus, s, across), t, fold.leaving)), kFilm, 0.5);
        if (!found) misses.push_back("no film across the last leg at " + std::to_string(s) + " mm");
    }
    return misses;
}

std::string joined(const std::vector<std::string>& lines) {
    std::string all;
    for (const std::string& l : lines) all += l + "; ";
    return all;
}

LensSystem codeV(const std::string& text) { return buildLensSystem(parseCodeV(text, "folded.seq")); }

}  // namespace

// A flat mirror at 45 degrees 20 mm behind the singlet (ADE 45, BEN) sends the beam along -y: ray ink
// below the mirror down to the film, lying flat at the back focal distance, and none past the mirror
// along -z. The same singlet unfolded, drawn along its axis, misses all of it.
TEST(FoldedPictures, AFoldMirrorAt45DegreesSendsTheBeamAlongMinusY) {
    const double bfd = backFocalDistance();
    const FoldedAxis fold = foldAxis({-25, 0}, {45}, {}, bfd - 20);
    ASSERT_NEAR(fold.leaving.z, 0, 1e-12);
    ASSERT_NEAR(fold.leaving.y, -1, 1e-12);
    const LensSystem folded = codeV(kSinglet + "s 0 -40 refl\nade 45; ben\n" + kPupil);
    const std::vector<std::string> misses = foldMisses(folded, fold);
    EXPECT_TRUE(misses.empty()) << joined(misses);
    const LensSystem unfolded = codeV("rdm\nso 0 1e10\ns 100 5 1.6,40\nsto\ns -150 97\n" + kPupil);
    EXPECT_NE(joined(foldMisses(unfolded, fold)).find("a ray straight on past mirror 1"), std::string::npos);
}

// Three fold mirrors (ADE 45, -45, 45, each with BEN) make a staircase: down 25 mm, on along -z 25 mm,
// down to the focus. Every leg, every mirror and the film are drawn where the reflection law puts them.
TEST(FoldedPictures, ThreeFoldMirrorsDrawTheStaircaseTheReflectionLawPredicts) {
    const double bfd = backFocalDistance();
    const FoldedAxis fold = foldAxis({-25, 0}, {45, -45, 45}, {25, 25}, bfd - 70);
    ASSERT_NEAR(fold.mirrors[2].z, -50, 1e-12);
    ASSERT_NEAR(fold.mirrors[2].y, -25, 1e-12);
    ASSERT_NEAR(fold.leaving.y, -1, 1e-12);
    const std::string folds = "s 0 -25 refl\nade 45; ben\ns 0 25 refl\nade -45; ben\ns 0 -27.4 refl\nade 45; ben\n";
    const LensSystem folded = codeV(kSinglet + folds + kPupil);
    const std::vector<std::string> misses = foldMisses(folded, fold);
    EXPECT_TRUE(misses.empty()) << joined(misses);
    const LensSystem unfolded = codeV("rdm\nso 0 1e10\ns 100 5 1.6,40\nsto\ns -150 97\n" + kPupil);
    const std::string unfoldedMisses = joined(foldMisses(unfolded, fold));
    for (const char* miss : {"a ray straight on past mirror 1", "no ray after mirror 1", "no ray after mirror 2"})
        EXPECT_NE(unfoldedMisses.find(miss), std::string::npos) << miss;
}

}  // namespace lenslab::test
