// Folded lenses drawn right, read back as pixels: a Schmidt-Cassegrain sketch written here (a flat
// corrector, a spherical primary with its image behind it, a convex secondary on the corrector) and
// the bundled Mangin reflex. Rays come from the scene, fold at the mirrors and reach the film through
// the primary's hole; the hole is drawn empty; the thick-lens model, which cannot fold, draws nothing.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "DiagramStyle.h"
#include "DiagramTestSupport.h"

namespace lenslab::test {
namespace {

using namespace diagram_style;

// Zemax coordinates, light along +z: the corrector (5 mm, n 1.5168) at 0, the primary (R -800,
// f 400) 250 behind it, the secondary (R -600, f -300) on the corrector's back, the film 300 behind
// the secondary. The primary's focus lies 150 beyond the secondary, which images it 300 away at
// magnification 2: EFL 800, the image 50 mm behind the primary. The corrector's back carries the
// secondary's shadow (21 mm).
constexpr double kPrimaryR = 800, kSecondaryR = 600, kPrimaryZ = -255, kSecondaryZ = -5;  // lens z
constexpr const char* kSchmidtCassegrain = R"(VERS 160720 18 100027
MODE SEQ
NAME Schmidt-Cassegrain sketch
UNIT MM X W X CM MR CPMM
ENPD 100
SURF 0
  CURV 0.0 0 0 0 0 ""
  DISZ INFINITY
SURF 1
  STOP
  CURV 0.0 0 0 0 0 ""
  DISZ 5
  GLAS ___BLANK 1 0 1.5168 64.17 0 0 0 0 0 0
  DIAM 52 0 0 0 1 ""
SURF 2
  CURV 0.0 0 0 0 0 ""
  DISZ 250
  DIAM 52 0 0 0 1 ""
  OBSC 0 21 0
SURF 3
  CURV -1.25E-3 0 0 0 0 ""
  MIRR 2 0
  DISZ -250
  GLAS MIRROR 0 0 1.5 40 0 0 0 0 0 0
  DIAM 54 0 0 0 1 ""
SURF 4
  CURV -1.6666666666666667E-3 0 0 0 0 ""
  MIRR 2 0
  DISZ 300
  GLAS MIRROR 0 0 1.5 40 0 0 0 0 0 0
  DIAM 21 0 0 0 1 ""
SURF 5
  CURV 0.0 0 0 0 0 ""
  DISZ 0
)";

LensSystem schmidtCassegrain() {
    const std::string path = ::testing::TempDir() + "/schmidt-cassegrain-sketch.zmx";
    std::ofstream(path) << kSchmidtCassegrain;
    const LensSystem lens = loadLensSystem(path);
    std::filesystem::remove(path);
    return lens;
}

ZY operator+(ZY a, ZY b) { return {a.z + b.z, a.y + b.y}; }
ZY operator*(double s, ZY a) { return {s * a.z, s * a.y}; }
double dot(ZY a, ZY b) { return a.z * b.z + a.y * b.y; }

// A meridional ray (from p along the unit vector d) reflected by the sphere of radius r whose vertex
// is at z = vertex and whose centre lies at vertex + r (both mirrors here are centred toward the
// scene): p becomes the hit on the vertex's side, d the reflected direction.
void reflect(double vertex, double r, ZY& p, ZY& d) {
    const ZY centre{vertex + r, 0};
    const ZY m{p.z - centre.z, p.y};
    const double b = dot(m, d), c = dot(m, m) - r * r;
    const double t1 = -b - std::sqrt(b * b - c), t2 = -b + std::sqrt(b * b - c);
    const ZY p1 = p + t1 * d, p2 = p + t2 * d;
    p = std::abs(p1.z - vertex) < std::abs(p2.z - vertex) ? p1 : p2;  // the side of the sphere at the vertex
    const ZY n = (1 / r) * ZY{p.z - centre.z, p.y};
    d = d + (-2 * dot(d, n)) * n;
}

ZY midpoint(ZY a, ZY b) { return {0.5 * (a.z + b.z), 0.5 * (a.y + b.y)}; }

}  // namespace

// Each arriving ray of the axial fan takes the path a two-sphere trace written here gives it: parallel
// to the axis through the corrector (a flat plate), reflected by the primary, then by the secondary,
// through the primary's hole to the film. Its folded legs show on the picture in the exact rays'
// colour, and the primary is drawn with no mirror where that light passes it.
TEST(CatadioptricPictures, SchmidtCassegrainFoldsThroughThePrimarysHole) {
    const LensSystem lens = schmidtCassegrain();
    ASSERT_EQ(lens.surfaces.size(), 4u);
    ASSERT_TRUE(lens.surfaces[2].mirror && lens.surfaces[3].mirror);
    ASSERT_NEAR(lens.surfaces[2].z, kPrimaryZ, 1e-9);
    ASSERT_NEAR(lens.surfaces[3].z, kSecondaryZ, 1e-9);
    DiagramOptions o;
    o.fieldHeight = 5;  // a telescope's field: 0.36 degrees
    const DiagramPicture picture = layoutDiagram(lens, o);
    const RgbaImage image = renderDiagram(lens, o);

    int arriving = 0;
    double widestAtPrimary = 0;  // where the light from the secondary crosses the primary's plane
    for (const FanRay& ray : picture.rays) {
        if (ray.offAxis || ray.blocked) continue;
        ++arriving;
        // start, corrector front and back, primary, secondary, film
        ASSERT_EQ(ray.points.size(), 6u);
        ZY p = ray.points[0], d{-1, 0};
        reflect(kPrimaryZ, kPrimaryR, p, d);
        EXPECT_NEAR(ray.points[3].z, p.z, 1e-6);
        EXPECT_NEAR(ray.points[3].y, p.y, 1e-6);
        reflect(kSecondaryZ, kSecondaryR, p, d);
        EXPECT_NEAR(ray.points[4].z, p.z, 1e-6);
        EXPECT_NEAR(ray.points[4].y, p.y, 1e-6);
        const ZY film = p + ((ray.points[5].z - p.z) / d.z) * d;
        EXPECT_LT(ray.points[5].z, kPrimaryZ);  // behind the primary
        EXPECT_NEAR(ray.points[5].y, film.y, 1e-6);
        const ZY atPrimary = p + ((kPrimaryZ - p.z) / d.z) * d;
        widestAtPrimary = std::max(widestAtPrimary, std::abs(atPrimary.y));
        // The leg back to the secondary and the leg through the hole, in the exact rays' blue.
        for (const ZY& q : {midpoint(ray.points[3], ray.points[4]), midpoint(atPrimary, ray.points[5])})
            EXPECT_TRUE(showsNear(image, picture.view.toPicture(q), kExactRay)) << q.z << ", " << q.y;
    }
    // 9 rays over 1.2 times the stop: the outer two miss it, the middle three fall in the
    // secondary's shadow.
    EXPECT_EQ(arriving, 4);

    // The hole: no mirror drawn from the axis out to where the light crosses; the mirror beyond it.
    const Surface& primary = lens.surfaces[2];
    for (double y = -widestAtPrimary; y <= widestAtPrimary; y += widestAtPrimary / 4) {
        const Point2 p = picture.view.toPicture({primary.z - sag(primary, std::abs(y)), y});
        EXPECT_FALSE(showsNear(image, p, kMirror, 0.9)) << "at y = " << y;
    }
    const double outside = 0.5 * (widestAtPrimary + primary.apertureRadius);
    EXPECT_TRUE(showsNear(image, picture.view.toPicture({primary.z - sag(primary, outside), outside}), kMirror, 0.9));
}

// The thick lens cannot fold: overlay mode draws no thick-lens ray for a mirror lens (its legend says
// so), and the exact rays as in exact mode.
TEST(CatadioptricPictures, NoThickLensRaysThroughMirrors) {
    for (const LensSystem& lens : {schmidtCassegrain(), loadLensSystem(std::string(LENSLAB_SOURCE_DIR) +
                                                                       "/lenses/us4666259-ex1-reflex-500mm.zmx")}) {
        DiagramOptions o;
        o.mode = DiagramMode::Overlay;
        const DiagramPicture picture = layoutDiagram(lens, o);
        o.mode = DiagramMode::Exact;
        EXPECT_EQ(picture.rays.size(), layoutDiagram(lens, o).rays.size()) << lens.name;
        for (const FanRay& ray : picture.rays) EXPECT_EQ(ray.model, RayModel::Exact) << lens.name;
        o.mode = DiagramMode::Overlay;
        const RgbaImage image = renderDiagram(lens, o);
        int orange = 0;
        for (int y = 0; y < image.height; ++y)
            for (int x = 0; x < image.width; ++x) orange += showsColour(pixelAt(image, {double(x), double(y)}), kThickRay, 0.6);
        EXPECT_EQ(orange, 0) << lens.name;
    }
}

// The reflex lens (US 4,666,259 example 1; surfaces counted from 0 here): its Mangin primary
// (surfaces 2-4, silvered at 3) has a central hole, where the relay lenses sit and the light leaves
// for the film. Between two relay elements, where the Mangin's glass would be were it solid, the
// picture shows no glass; outside the hole it does. The light reflected by the Mangin reaches the
// secondary (silvered at 6) and the film.
TEST(CatadioptricPictures, ReflexManginPrimaryHasItsHoleAndTheLightFolds) {
    const LensSystem lens = loadLensSystem(std::string(LENSLAB_SOURCE_DIR) + "/lenses/us4666259-ex1-reflex-500mm.zmx");
    ASSERT_TRUE(lens.surfaces[3].mirror && lens.surfaces[6].mirror);
    DiagramOptions o;
    const DiagramPicture picture = layoutDiagram(lens, o);
    const RgbaImage image = renderDiagram(lens, o);

    // z -67 mm lies inside the Mangin's glass (front face at -66 - sag, silvered face near -80) and in
    // the air between the relay element 8-9 (ending at -62 - sag) and the next, 10 (from -69.5 + sag),
    // for |y| <= 9.
    const Surface &front = lens.surfaces[2], &relayRear = lens.surfaces[9], &relayNext = lens.surfaces[10];
    for (double y : {-9.0, -6.0, 6.0, 9.0}) {
        ASSERT_LT(-67.0, profileZ(front, y));
        ASSERT_LT(-67.0, profileZ(relayRear, y));
        ASSERT_GT(-67.0, profileZ(relayNext, y));
        EXPECT_FALSE(showsNear(image, picture.view.toPicture({-67.0, y}), kGlass, 0.9)) << "hole at y = " << y;
    }
    for (double y : {-30.0, 30.0}) EXPECT_TRUE(showsNear(image, picture.view.toPicture({-72.0, y}), kGlass, 0.9)) << y;

    int folded = 0;
    for (const FanRay& ray : picture.rays) {
        if (ray.blocked) continue;
        ++folded;
        // start, then a hit per surface: the Mangin's silvered face is point 4, the secondary's point 7.
        ASSERT_GE(ray.points.size(), 9u);
        EXPECT_GT(ray.points[7].z, ray.points[4].z);  // the reflected light runs back toward the scene
        // The leg in air from the Mangin back to the secondary's element.
        EXPECT_TRUE(showsNear(image, picture.view.toPicture(midpoint(ray.points[5], ray.points[6])), kExactRay))
            << ray.points[5].z << ", " << ray.points[5].y;
    }
    EXPECT_GE(folded, 6);
}

}  // namespace lenslab::test
