// What a frame's setup costs through each lens, as CPU seconds measured in one run: the shared
// world (scenes/shared-dgauss.pbrt) at 160 x 160 through dgauss.50mm and through the Sony 55 mm
// (.zmx, five aspheres, a cover glass 1 mm before the film, dispersive: its bounds are measured per
// band of wavelengths from 360 to 830 nm), one thread, the lenses interleaved round by round so that load from other processes
// falls on both alike, best of the rounds. The setup is PreparedFrame's (scene parse, camera:
// focus, exit-pupil bounds, wavelength tables; Embree); the scene's share is the perspective row.
//   camera_setup [rounds=3]
#include <cstdio>
#include <string>
#include <vector>

#include "ProcessCpuTime.h"
#include "render/PreparedFrame.h"

namespace {

struct Case {
    std::string name, lens;  // lens empty: the scene as written (its own realistic camera)
};

}  // namespace

int main(int argc, char** argv) {
    const int rounds = argc > 1 ? std::stoi(argv[1]) : 3;
    const std::string root = LENSLAB_SOURCE_DIR;
    const std::vector<Case> cases = {
        {"dgauss.50mm", root + "/lenses/dgauss.50mm.dat"},
        {"Sony 55 mm (.zmx)", root + "/lenses/us2015-0092100-ex1-55mm.zmx"},
    };
    std::vector<double> best(cases.size(), 1e300);
    for (int r = 0; r < rounds; ++r)
        for (std::size_t c = 0; c < cases.size(); ++c) {
            lenslab::RenderSettings s;
            s.scenePath = root + "/scenes/shared-dgauss.pbrt";
            s.camera.lensFile = cases[c].lens;
            s.width = s.height = 160;
            s.threads = 1;
            const double cpu0 = lenslab::bench::processCpuSeconds();
            const lenslab::PreparedFrame frame(s);
            best[c] = std::min(best[c], lenslab::bench::processCpuSeconds() - cpu0);
        }
    std::printf("160 x 160, 1 thread, best of %d interleaved rounds; CPU = user + system\n\n", rounds);
    std::printf("| lens | setup CPU s | against dgauss.50mm |\n|---|---|---|\n");
    for (std::size_t c = 0; c < cases.size(); ++c)
        std::printf("| %s | %.3f | %.2fx |\n", cases[c].name.c_str(), best[c], best[c] / best[0]);
    return 0;
}
