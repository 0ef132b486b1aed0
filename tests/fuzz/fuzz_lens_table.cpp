// libFuzzer target: arbitrary bytes as a lens table, in every layout mode. The parser and the
// geometry builder may refuse input only with LensTableError; anything else escaping, a crash, a
// sanitizer report or a broken invariant of an accepted lens is a finding.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>

#include "FuzzCheck.h"
#include "prescription/LensSystem.h"
#include "prescription/LensTable.h"

using namespace lenslab;
using lenslab::fuzz::check;

namespace {

void checkLens(const LensSystem& lens) {
    check(!lens.surfaces.empty(), "an accepted lens has surfaces");
    check(lens.stopIndex >= 0 && lens.stopIndex < static_cast<int>(lens.surfaces.size()), "stop index in range");
    check(lens.stop().isStop, "the stop index names the stop");
    check(lens.frontZ() == 0, "the front vertex is the origin");
    for (std::size_t i = 0; i < lens.surfaces.size(); ++i) {
        const Surface& s = lens.surfaces[i];
        check(std::isfinite(s.z) && std::isfinite(s.curvature), "finite geometry");
        check(s.apertureRadius > 0 && std::isfinite(s.apertureRadius), "positive finite aperture");
        check(s.indexAfter >= 1 && std::isfinite(s.indexAfter), "index >= 1");
        check(i == 0 || s.z <= lens.surfaces[i - 1].z, "surfaces run toward the film");
        check(std::isfinite(sag(s, s.apertureRadius)), "finite sag at the rim");
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    for (std::optional<TableLayout> layout : {std::optional<TableLayout>{}, std::optional{TableLayout::GapBefore},
                                              std::optional{TableLayout::GapAfter}}) {
        try {
            checkLens(buildLensSystem(parseLensTable(text, "fuzz.dat", layout)));
        } catch (const LensTableError& e) {
            check(!e.problem().empty(), "a refusal says why");
        }
    }
    return 0;
}
