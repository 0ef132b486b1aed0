// Coatings: their text, the default for a real lens's air-glass surfaces, and the reflectance and
// transmittance of bare and coated surfaces against closed forms (Fresnel's equations, the
// quarter-wave layer's textbook values) and invariants (R + T = 1, reciprocity).
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <filesystem>
#include <random>

#include "PrescriptionRows.h"
#include "prescription/LensSystem.h"
#include "trace/ThinFilm.h"

using namespace lenslab;
using lenslab::test::buildRows;
using lenslab::test::row;
using lenslab::test::stopRow;

namespace {

// Fresnel's power reflectances for s and p light from n1 to n2 at incidence cosine c1, written out.
double fresnelUnpolarised(double n1, double n2, double c1) {
    const double s1 = std::sqrt(1 - c1 * c1), s2 = n1 * s1 / n2;
    if (s2 >= 1) return 1;
    const double c2 = std::sqrt(1 - s2 * s2);
    const double rs = (n1 * c1 - n2 * c2) / (n1 * c1 + n2 * c2);
    const double rp = (n2 * c1 - n1 * c2) / (n2 * c1 + n1 * c2);
    return 0.5 * (rs * rs + rp * rp);
}

double reflectance(const std::string& coating, double n1, double n2, double cos1, double nm) {
    return thinFilmResponse(n1, n2, parseCoating(coating).layers, false, cos1, nm).reflectance;
}

}  // namespace

TEST(CoatingText, ReadsQuarterWavesStacksAndBareGlass) {
    EXPECT_TRUE(parseCoating("none").bare());
    EXPECT_TRUE(parseCoating(" NONE ").bare());
    const Coating mgf2 = parseCoating("MgF2");
    ASSERT_EQ(mgf2.layers.size(), 1u);
    EXPECT_DOUBLE_EQ(mgf2.layers[0].index, 1.38);
    EXPECT_DOUBLE_EQ(mgf2.layers[0].thicknessNm, 550 / (4 * 1.38));  // a quarter wave at 550 nm
    EXPECT_DOUBLE_EQ(parseCoating("MGF2@600").layers[0].thicknessNm, 600 / (4 * 1.38));
    const Coating stack = parseCoating("MgF2+2.05:2q+1.63:80nm@500");
    ASSERT_EQ(stack.layers.size(), 3u);
    EXPECT_DOUBLE_EQ(stack.layers[1].index, 2.05);
    EXPECT_DOUBLE_EQ(stack.layers[1].thicknessNm, 2 * 500 / (4 * 2.05));
    EXPECT_DOUBLE_EQ(stack.layers[2].thicknessNm, 80);
    EXPECT_EQ(stack.text, "MgF2+2.05:2q+1.63:80nm@500");
}

TEST(CoatingText, RefusesWhatItCannotRead) {
    const auto problem = [](const std::string& text) {
        try {
            parseCoating(text);
        } catch (const CoatingError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_NE(problem("Unobtainium").find("unknown material 'Unobtainium' (known: MgF2 1.38"), std::string::npos);
    EXPECT_NE(problem("MgF2:80").find("needs a unit"), std::string::npos);
    EXPECT_NE(problem("MgF2@5").find("design wavelength '5'"), std::string::npos);
    EXPECT_NE(problem("MgF2++SiO2").find("empty layer"), std::string::npos);
    EXPECT_NE(problem("0.5").find("must lie in [1, 5]"), std::string::npos);
    EXPECT_NE(problem("").find("empty coating"), std::string::npos);
}

// The numbers: a quarter wave of MgF2 (1.38) at 550 nm on glass of index 1.52, normal
// incidence, no dispersion. At the design wavelength R = ((n0 ns - n1^2) / (n0 ns + n1^2))^2.
TEST(ThinFilm, QuarterWaveMgF2OnCrownGlass) {
    const struct { double nm, percent; } expected[] = {{550, 1.26}, {400, 2.21}, {450, 1.62}, {650, 1.44}, {700, 1.60}};
    for (const auto& e : expected)
        EXPECT_NEAR(100 * reflectance("MgF2@550", 1, 1.52, 1, e.nm), e.percent, 0.005) << e.nm << " nm";
    EXPECT_NEAR(reflectance("MgF2@550", 1, 1.52, 1, 550), std::pow((1.52 - 1.38 * 1.38) / (1.52 + 1.38 * 1.38), 2), 1e-12);
    EXPECT_NEAR(100 * reflectance("none", 1, 1.52, 1, 550), 4.26, 0.005);
}

TEST(ThinFilm, BareGlassFollowsFresnelFromNormalToGrazing) {
    for (double n2 : {1.5, 1.9}) {
        EXPECT_NEAR(reflectance("none", 1, n2, 1, 550), std::pow((n2 - 1) / (n2 + 1), 2), 1e-14);
        for (double degrees : {10.0, 45.0, 70.0, 85.0, 89.9, 89.9999})
            EXPECT_NEAR(reflectance("none", 1, n2, std::cos(degrees * M_PI / 180), 550),
                        fresnelUnpolarised(1, n2, std::cos(degrees * M_PI / 180)), 1e-12)
                << n2 << " at " << degrees << " deg";
        EXPECT_NEAR(reflectance("none", 1, n2, 1e-9, 550), 1, 1e-8);  // grazing: all reflected
        EXPECT_EQ(reflectance("none", 1, n2, 0, 550), 1);
        // Brewster's angle: p light passes, R is half of s's.
        const double brewster = std::atan(n2), c = std::cos(brewster), c2 = std::cos(std::asin(std::sin(brewster) / n2));
        const double rs = (c - n2 * c2) / (c + n2 * c2);
        EXPECT_NEAR(reflectance("none", 1, n2, c, 550), 0.5 * rs * rs, 1e-14);
    }
    // Inside the glass: the same closed form up to the critical angle, total reflection past it.
    EXPECT_NEAR(reflectance("none", 1.5, 1, std::cos(0.5), 550), fresnelUnpolarised(1.5, 1, std::cos(0.5)), 1e-12);
    const double critical = std::asin(1 / 1.5);
    const InterfaceResponse tir = thinFilmResponse(1.5, 1, parseCoating("MgF2").layers, true, std::cos(critical + 0.01), 550);
    EXPECT_NEAR(tir.reflectance, 1, 1e-12);
    EXPECT_EQ(tir.transmittance, 0);
}

// Lossless stacks conserve energy at every angle and wavelength, from either side; transmittance
// is the same both ways through the same stack (reciprocity).
TEST(ThinFilm, LosslessStacksConserveEnergyAndAreReciprocal) {
    std::mt19937 rng(30);
    std::uniform_real_distribution<double> index(1.3, 2.4), thickness(5, 400), unit(0, 1), glass(1.45, 1.95);
    for (int trial = 0; trial < 200; ++trial) {
        std::vector<CoatingLayer> layers(1 + trial % 5);
        for (CoatingLayer& l : layers) l = {index(rng), thickness(rng)};
        const double n = glass(rng), nm = 380 + 400 * unit(rng), cos1 = unit(rng);
        const InterfaceResponse in = thinFilmResponse(1, n, layers, false, cos1, nm);
        EXPECT_NEAR(in.reflectance + in.transmittance, 1, 1e-12);
        // The same ray reversed: inside the glass at the refracted angle, the layers met in reverse.
        const double cosGlass = std::sqrt(1 - (1 - cos1 * cos1) / (n * n));
        const InterfaceResponse out = thinFilmResponse(n, 1, layers, true, cosGlass, nm);
        EXPECT_NEAR(out.reflectance + out.transmittance, 1, 1e-12);
        EXPECT_NEAR(out.transmittance, in.transmittance, 1e-12);
    }
}

// A half-wave layer is absent at its design wavelength (normal incidence): bare glass's R.
TEST(ThinFilm, HalfWaveLayerIsAbsentAtItsDesignWavelength) {
    EXPECT_NEAR(reflectance("2.05:2q@600", 1, 1.6, 1, 600), reflectance("none", 1, 1.6, 1, 600), 1e-14);
    EXPECT_GT(std::fabs(reflectance("2.05:2q@600", 1, 1.6, 1, 450) - reflectance("none", 1, 1.6, 1, 450)), 0.01);
}

// One layer at oblique incidence against Airy's sum of the multiply reflected waves, written here
// with complex amplitudes: r = (r12 + r23 e^{2i delta}) / (1 + r12 r23 e^{2i delta}), delta the
// layer's phase thickness 2 pi n d cos(theta_layer) / lambda. A phase thickness without the layer's
// cosine (every angle coated as at normal incidence) is off by 0.004 to 0.08 at 30 to 75 deg.
TEST(ThinFilm, OneLayerAtObliqueIncidenceIsAirysSum) {
    using C = std::complex<double>;
    const double n1 = 1, nf = 1.38, n2 = 1.72, d = 137.5;
    const auto airy = [&](double cos1, double nm) {
        const double s1 = std::sqrt(1 - cos1 * cos1);
        const double cf = std::sqrt(1 - std::pow(n1 * s1 / nf, 2)), c2 = std::sqrt(1 - std::pow(n1 * s1 / n2, 2));
        const C phase = std::exp(C(0, 2 * (2 * M_PI * nf * d * cf / nm)));
        double r = 0;
        for (const bool p : {false, true}) {
            const auto fresnel = [p](double na, double ca, double nb, double cb) {
                return p ? (nb * ca - na * cb) / (nb * ca + na * cb) : (na * ca - nb * cb) / (na * ca + nb * cb);
            };
            const double r12 = fresnel(n1, cos1, nf, cf), r23 = fresnel(nf, cf, n2, c2);
            r += 0.5 * std::norm((r12 + r23 * phase) / (1.0 + r12 * r23 * phase));
        }
        return r;
    };
    const std::vector<CoatingLayer> layer = {{nf, d}};
    for (const double degrees : {0.0, 30.0, 45.0, 60.0, 75.0})
        for (const double nm : {450.0, 550.0, 650.0}) {
            const double cos1 = std::cos(degrees * M_PI / 180);
            EXPECT_NEAR(thinFilmResponse(n1, n2, layer, false, cos1, nm).reflectance, airy(cos1, nm), 1e-12)
                << degrees << " deg, " << nm << " nm";
        }
}

// Real lenses: every refracting surface between air and glass is coated with MgF2 unless its row
// says otherwise; cemented surfaces, the stop and mirrors are bare. Checked on every bundled lens,
// the course's tables among them, against the surfaces' media counted here.
TEST(CoatingDefault, RealLensesHaveMgF2OnEveryAirGlassSurface) {
    int lenses = 0;
    for (const auto& entry : std::filesystem::directory_iterator(LENSLAB_SOURCE_DIR "/lenses")) {
        if (!isLensFileName(entry.path().string())) continue;
        ++lenses;
        const LensSystem lens = loadLensSystem(entry.path().string());
        int coated = 0, airGlass = 0;
        for (std::size_t i = 0; i < lens.surfaces.size(); ++i) {
            const Surface& s = lens.surfaces[i];
            const double before = i == 0 ? 1.0 : lens.surfaces[i - 1].indexAfter;
            const bool isAirGlass = !s.mirror && ((before == 1) != (s.indexAfter == 1));
            airGlass += isAirGlass;
            coated += !s.coating.bare();
            EXPECT_EQ(s.coating.bare(), !isAirGlass) << entry.path() << " surface " << i + 1;
            if (isAirGlass) {
                EXPECT_EQ(s.coating.text, "MgF2@550");
                EXPECT_TRUE(s.coating.isDefault);
            }
        }
        EXPECT_EQ(coated, airGlass) << entry.path();
        EXPECT_GT(airGlass, 1) << entry.path();
    }
    EXPECT_GE(lenses, 13);
    // The course's double Gauss (lenses/dgauss.dat, read row by row): rows 1-3, 5, 7, 9-11 lie
    // between air and glass; 4 and 8 are cemented; 6 is the stop.
    const LensSystem dgauss = loadLensSystem(LENSLAB_SOURCE_DIR "/lenses/dgauss.dat");
    int airGlass = 0;
    for (const Surface& s : dgauss.surfaces) airGlass += !s.coating.bare();
    EXPECT_EQ(airGlass, 8);
}

TEST(CoatingDefault, ARowsCoatingOverridesTheDefault) {
    const LensSystem lens = buildLensSystem(parseLensTable(
        "50 5 1.5 20 coat=none\n-50 5 1 20 coat=MgF2+ZrO2:2q\n0 5 0 10\n40 4 1.5168 18 N-BK7 coat=SiO2@500\n-80 0 1 18\n",
        "rows.dat"));
    EXPECT_TRUE(lens.surfaces[0].coating.bare());
    EXPECT_FALSE(lens.surfaces[0].coating.isDefault);
    EXPECT_EQ(lens.surfaces[1].coating.layers.size(), 2u);
    EXPECT_EQ(lens.surfaces[3].coating.text, "SiO2@500");
    EXPECT_EQ(lens.surfaces[3].mediumAfter.name, "N-BK7");
    EXPECT_TRUE(lens.surfaces[4].coating.isDefault);
    try {
        buildLensSystem(parseLensTable("50 5 1.5 20 coat=MgF2:3\n-50 0 1 20\n0 0 0 10\n", "bad.dat",
                                       TableLayout::GapAfter));
        FAIL();
    } catch (const LensTableError& e) {
        EXPECT_EQ(e.line(), 1);
        EXPECT_NE(std::string(e.what()).find("needs a unit"), std::string::npos) << e.what();
    }
    try {
        parseLensTable("50 5 1.5 20 coat=none coat=MgF2\n-50 0 1 20\n", "bad.dat");
        FAIL();
    } catch (const LensTableError& e) {
        EXPECT_NE(std::string(e.what()).find("a second coat="), std::string::npos) << e.what();
    }
}

// The surface's response uses the glass's index at the wavelength asked and meets the layers from
// the air side whichever way the light goes: a stack on a rear (glass-to-air) surface seen from the
// film is the stack as written; seen from inside the glass, reversed.
TEST(SurfaceResponse, UsesDispersionAndTheCoatingsOuterSide) {
    std::vector<LensTableRow> rows = {row(50, 5, 1.6, 20), row(-50, 5, 1, 20), stopRow(20, 10)};
    rows[0].abbe = 40;  // a dispersive model glass
    rows[1].coating = "MgF2+ZrO2";
    const LensSystem lens = buildRows(rows);
    const Medium& glass = lens.surfaces[0].mediumAfter;
    const std::vector<CoatingLayer>& front = lens.surfaces[0].coating.layers;  // the default, MgF2
    for (double nm : {420.0, 587.5618, 680.0}) {
        const double n = refractiveIndex(glass, nm);
        EXPECT_DOUBLE_EQ(surfaceResponse(lens, 0, true, 0.8, nm).reflectance, thinFilmResponse(1, n, front, false, 0.8, nm).reflectance);
    }
    EXPECT_NE(surfaceResponse(lens, 0, true, 1, 420).reflectance, surfaceResponse(lens, 0, true, 1, 680).reflectance);
    const std::vector<CoatingLayer>& rear = lens.surfaces[1].coating.layers;
    const double n = refractiveIndex(glass, 500);
    EXPECT_DOUBLE_EQ(surfaceResponse(lens, 1, false, 0.9, 500).reflectance, thinFilmResponse(1, n, rear, false, 0.9, 500).reflectance);
    const double cosGlass = std::sqrt(1 - (1 - 0.81) / (n * n));
    EXPECT_DOUBLE_EQ(surfaceResponse(lens, 1, true, cosGlass, 500).reflectance, thinFilmResponse(n, 1, rear, true, cosGlass, 500).reflectance);
    // The stack is not symmetric: met in the wrong order it reflects differently.
    EXPECT_GT(std::fabs(thinFilmResponse(1, n, rear, true, 1, 500).reflectance - thinFilmResponse(1, n, rear, false, 1, 500).reflectance), 1e-3);
}
