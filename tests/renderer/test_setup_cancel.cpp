// Lens setup that scales: the exit-pupil bounds report progress and stop at once on cancel, also
// for a lens at the surface limit.
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "firstorder/ExitPupilBounds.h"
#include "firstorder/FirstOrder.h"
#include "prescription/LensSystem.h"
#include "prescription/LensTable.h"
#include "cameras/RealisticCamera.h"
#include "TestScenes.h"

namespace lenslab {
namespace {

// kMaxLensSurfaces surfaces: weak biconvex elements (f ~ 50 m each, ~410 mm together), the stop
// in the middle; gap-before layout.
std::string tableAtTheSurfaceLimit() {
    std::string t;
    for (int i = 0; i < kMaxLensSurfaces; ++i) {
        const std::string gap = i == 0 ? " 0 " : " 0.5 ";
        if (i == kMaxLensSurfaces / 2 - 1) t += "0" + gap + "0 18\n";
        else t += std::string(i % 2 ? "-50000" : "50000") + gap + (i % 2 ? "1" : "1.5") + " 20\n";
    }
    return t;
}

LensSystem lensAtTheSurfaceLimit() { return buildLensSystem(parseLensTable(tableAtTheSurfaceLimit(), "limit.dat")); }

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
    const RealisticParams p = realisticParams(test::lensPath("dgauss.50mm.dat"), std::nullopt, 10000);
    double last = 0;
    const RealisticCamera camera(p, Transform{}, 64, 64, 0.5, nullptr, [&](double f) { last = f; });
    EXPECT_EQ(last, 1.0);
    std::atomic<bool> cancel{true};
    EXPECT_THROW(RealisticCamera(p, Transform{}, 64, 64, 0.5, &cancel), SetupCancelled);
}

// Through the render API: a cancel set while the huge lens sets up ends the render at once.
TEST(SetupCancel, CancellingARenderStopsTheLensSetup) {
    test::TempDir dir;
    const std::string lens = dir.write("limit.dat", tableAtTheSurfaceLimit());
    const std::string scene = dir.write("s.pbrt", "Scale 1000 1000 1000\nCamera \"realistic\" \"string specfile\" \"limit.dat\" "
                                                  "\"float focaldistance\" 20000\nFilm \"image\"\nWorldBegin\nWorldEnd\n");
    RenderSettings s;
    s.scenePath = scene;
    s.width = s.height = 64;
    s.spp = 1;
    std::atomic<bool> cancel{false};
    std::thread canceller([&] {
        std::this_thread::sleep_for(std::chrono::milliseconds(150));
        cancel = true;
    });
    const auto start = std::chrono::steady_clock::now();
    EXPECT_THROW(renderScene(s, {}, &cancel), RenderCancelled);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    canceller.join();
    EXPECT_LT(seconds, 1.15);  // 0.15 s before the cancel, then well under a second
}

}  // namespace
}  // namespace lenslab
