// Real prescriptions: a course table written by hand as .zmx reads to the same first-order data,
// catalog glasses make a cemented achromat (nearly) free of colour where a singlet is not, and a
// lens's data move with the wavelength as its glasses say.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "firstorder/FirstOrder.h"
#include "settings/LensAnalysis.h"
#include "prescription/Medium.h"
#include "OpticsTestHelpers.h"

using namespace lenslab;
using namespace lenslab::test;

namespace {


}  // namespace

TEST(RealLenses, CourseTableWrittenAsZemaxHasTheSameFirstOrderData) {
    const LensSystem table = loadLensSystem(kLensesDir + "dgauss.50mm.dat");
    const LensSystem zmx = loadLensSystem(std::string(LENSLAB_SOURCE_DIR) + "/tests/optics/data/dgauss.50mm.zmx");
    ASSERT_EQ(zmx.format, "zmx");
    const LensAnalysis a = analyzeLens(table, 4.0, 2000);
    const LensAnalysis b = analyzeLens(zmx, 4.0, 2000);
    EXPECT_NEAR(a.firstOrder.efl, b.firstOrder.efl, 1e-9);
    EXPECT_NEAR(a.firstOrder.backFocalDistance, b.firstOrder.backFocalDistance, 1e-9);
    EXPECT_NEAR(a.firstOrder.zF, b.firstOrder.zF, 1e-9);
    EXPECT_NEAR(a.firstOrder.zP, b.firstOrder.zP, 1e-9);
    EXPECT_NEAR(a.firstOrder.zPPrime, b.firstOrder.zPPrime, 1e-9);
    EXPECT_NEAR(a.pupils.entrance.z, b.pupils.entrance.z, 1e-9);
    EXPECT_NEAR(a.pupils.exit.diameter, b.pupils.exit.diameter, 1e-9);
    EXPECT_NEAR(a.aperture.fstopMin, b.aperture.fstopMin, 1e-9);
    EXPECT_NEAR(a.focus.imageZExact, b.focus.imageZExact, 1e-9);
    // The table has one index per element; the .zmx names Abbe numbers, so only it has colour.
    EXPECT_FALSE(table.isDispersive());
    EXPECT_TRUE(zmx.isDispersive());
    EXPECT_EQ(a.chromatic.longitudinalColour, 0);
    EXPECT_NE(b.chromatic.longitudinalColour, 0);
}

TEST(RealLenses, CementedAchromatBringsFAndCTogether) {
    // Thorlabs AC254-100-A, N-BK7 / SF5 from the catalog. A singlet of the same focal length in
    // N-BK7 alone spreads F and C by about f / Vd = 100 / 64.17 = 1.56 mm; the achromat leaves a
    // residual of a tenth of that (what its glass pair and bending allow; here 0.13 mm).
    const LensSystem doublet = loadLensSystem(kLensesDir + "ac254-100-a.dat");
    const double fF = computeFirstOrder(atWavelength(doublet, kWavelengthF)).efl;
    const double fC = computeFirstOrder(atWavelength(doublet, kWavelengthC)).efl;
    const double fd = computeFirstOrder(doublet).efl;
    EXPECT_LT(std::fabs(fC - fF), 0.15);
    EXPECT_GT(std::fabs(fC - fF), 0.05);  // not zero: the index really changes with the line
    EXPECT_NEAR(fd, 100.07, 0.01);
    // The thin singlet of the same power, from the same catalog: f(l) = f_d (n_d - 1) / (n(l) - 1).
    const Medium bk7 = doublet.surfaces[1].mediumAfter;
    ASSERT_EQ(bk7.name, "N-BK7");
    const double nd = refractiveIndex(bk7, kWavelengthD);
    const double singletSpread =
        fd * (nd - 1) / (refractiveIndex(bk7, kWavelengthC) - 1) - fd * (nd - 1) / (refractiveIndex(bk7, kWavelengthF) - 1);
    EXPECT_NEAR(singletSpread, fd / 64.17, 0.01);
    EXPECT_GT(singletSpread, 10 * std::fabs(fC - fF));
}

TEST(RealLenses, WavelengthMovesTheFirstOrderDataAsTheGlassesSay) {
    // One N-BK7 singlet: the thick lensmaker's equation 1/f = (n - 1)(c1 - c2 + (n - 1) t c1 c2 / n).
    const double c1 = 0.01, c2 = -0.01, t = 1.2;
    const LensSystem lens = buildLensSystem(parseLensTable("0 0 0 16\n100 0.1 1.5168 20 N-BK7\n-100 1.2 0 20\n", "bk7.dat"));
    for (double nm : {404.66, 486.1327, 587.5618, 656.2725, 706.52}) {
        LensSettings s;
        s.wavelength = Setting{nm, "test"};
        const LensAnalysis a = analyzeLens(lens, s);
        const double n = refractiveIndex(lens.surfaces[1].mediumAfter, nm);
        EXPECT_NEAR(a.firstOrder.efl, 1 / ((n - 1) * (c1 - c2 + (n - 1) * t * c1 * c2 / n)), 1e-9 * a.firstOrder.efl) << nm;
        EXPECT_DOUBLE_EQ(a.lens.wavelength, nm);
        EXPECT_DOUBLE_EQ(a.lens.surfaces[1].indexAfter, n);
    }
    // The colour block at infinity: F' of each line from the thick lens's back focal distance
    // BFL = f (1 - (n - 1) t c1 / n); blue focuses nearer the lens, so C - F is negative.
    auto rearFocusZ = [&](double nm) {
        const double n = refractiveIndex(lens.surfaces[1].mediumAfter, nm);
        const double f = 1 / ((n - 1) * (c1 - c2 + (n - 1) * t * c1 * c2 / n));
        return lens.rearZ() - f * (1 - (n - 1) * t * c1 / n);
    };
    const Chromatic colour = analyzeLens(lens, std::nullopt, std::numeric_limits<double>::infinity()).chromatic;
    EXPECT_NEAR(colour.imageZF, rearFocusZ(kWavelengthF), 1e-8);
    EXPECT_NEAR(colour.imageZC, rearFocusZ(kWavelengthC), 1e-8);
    EXPECT_NEAR(colour.longitudinalColour, rearFocusZ(kWavelengthC) - rearFocusZ(kWavelengthF), 1e-8);
    EXPECT_LT(colour.longitudinalColour, -1);  // about f / Vd = 100 / 64 mm
    // Schott's N-BK7 at the g line, 435.83 nm, is 1.52668: the index the lens is traced with.
    EXPECT_NEAR(atWavelength(lens, 435.8343).surfaces[1].indexAfter, 1.52668, 1e-5);
}

TEST(RealLenses, WavelengthBeyondGlassDataIsRefusedNamingItsSource) {
    LensSettings s;
    s.wavelength = Setting{3390, "--wavelength"};
    try {
        analyzeLens(loadLensSystem(kLensesDir + "ac254-100-a.dat"), s);
        FAIL();
    } catch (const std::exception& e) {
        EXPECT_STREQ(e.what(), "--wavelength: wavelength 3390 nm lies outside 180-2500 nm");
    }
}

TEST(RealLenses, TableGlassThatContradictsItsIndexIsRefused) {
    try {
        buildLensSystem(parseLensTable("0 0 0 20\n100 2 1.6200 30 N-BK7\n-100 2 0 30\n", "typo.dat"));
        FAIL();
    } catch (const LensTableError& e) {
        EXPECT_EQ(e.line(), 2);
        EXPECT_NE(std::string(e.what()).find("contradicts N-BK7 (SCHOTT), whose nd is 1.5168"), std::string::npos) << e.what();
    }
}

TEST(RealLenses, UnknownGlassNamesTheCatalogsAndTheNearestNames) {
    try {
        buildLensSystem(parseLensTable("0 0 0 20\n100 2 1.5168 30 N-BK8\n-100 2 0 30\n", "unknown.dat"));
        FAIL();
    } catch (const LensTableError& e) {
        EXPECT_EQ(e.line(), 2);
        const std::string m = e.what();
        EXPECT_NE(m.find("unknown glass 'N-BK8' (searched SCHOTT, OHARA"), std::string::npos) << m;
        EXPECT_NE(m.find("nearest: N-BK7"), std::string::npos) << m;
    }
}
