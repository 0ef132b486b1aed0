// Lens setup that scales: the exit-pupil bounds report progress and stop at once on cancel, also
// for a lens at the surface limit.
#include <gtest/gtest.h>

#include <chrono>

#include "ExitPupilBounds.h"
#include "FirstOrder.h"
#include "LensSystem.h"
#include "LensTable.h"
#include "RealisticCamera.h"
#include "TestScenes.h"

namespace lenslab {
namespace {

// kMaxLensSurfaces surfaces: weak biconvex elements (f ~ 50 m each, ~410 mm together), the stop
// in the middle; gap-before layout.
LensSystem lensAtTheSurfaceLimit() {
    std::string t;
    for (int i = 0; i < kMaxLensSurfaces; ++i) {
        const std::string gap = i == 0 ? " 0 " : " 0.5 ";
        if (i == kMaxLensSurfaces / 2 - 1) t += "0" + gap + "0 18\n";
        else t += std::string(i % 2 ? "-50000" : "50000") + gap + (i % 2 ? "1" : "1.5") + " 20\n";
    }
    return buildLensSystem(parseLensTable(t, "limit.dat"));
}

TEST(SetupCancel, ExitPupilBoundsOfALensAtTheSurfaceLimitStopAtOnceOnCancel) {
    const LensSystem lens = lensAtTheSurfaceLimit();
    ASSERT_EQ(int(lens.surfaces.size()), kMaxLensSurfaces);
    std::atomic<bool> cancel{false};
    std::vector<double> reported;
    std::chrono::steady_clock::time_point cancelledAt;
    ExitPupilBoundsOptions o;
    o.cancel = &cancel;
    o.progress = [&](double fraction) {
        reported.push_back(fraction);
        if (reported.size() == 3) {
            cancelledAt = std::chrono::steady_clock::now();
            cancel = true;
        }
    };
    EXPECT_THROW(computeExitPupilBounds(lens, computeFirstOrder(lens).zFPrime - 1, 20.0, o), SetupCancelled);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - cancelledAt).count();
    EXPECT_LT(seconds, 1.0);
    // One report per measured radius of 64, then it stopped: no radius after the cancel.
    EXPECT_EQ(reported, (std::vector<double>{1.0 / 64, 2.0 / 64, 3.0 / 64}));
}

TEST(SetupCancel, ProgressRisesToOneWhenNotCancelled) {
    const LensSystem lens = loadLensSystem(test::lensPath("dgauss.50mm.dat"));
    std::vector<double> reported;
    ExitPupilBoundsOptions o;
    o.progress = [&](double fraction) { reported.push_back(fraction); };
    const ExitPupilBounds b = computeExitPupilBounds(lens, computeFirstOrder(lens).zFPrime, 20.0, o);
    ASSERT_EQ(reported.size(), 64u);
    for (std::size_t k = 1; k < reported.size(); ++k) EXPECT_GT(reported[k], reported[k - 1]);
    EXPECT_EQ(reported.back(), 1.0);
    EXPECT_EQ(b.radiusCount(), 64);
}

TEST(SetupCancel, TheRealisticCameraPassesCancelAndProgressToItsSetup) {
    RealisticParams p;
    p.lensPath = test::lensPath("dgauss.50mm.dat");
    double last = 0;
    const RealisticCamera camera(p, Transform{}, 64, 64, 0.5, nullptr, [&](double f) { last = f; });
    EXPECT_EQ(last, 1.0);
    std::atomic<bool> cancel{true};
    EXPECT_THROW(RealisticCamera(p, Transform{}, 64, 64, 0.5, &cancel), SetupCancelled);
}

}  // namespace
}  // namespace lenslab
