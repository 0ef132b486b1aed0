#pragma once
// Random valid lenses for property tests: random radii (some flat), gaps, glasses and apertures,
// kept only when the lens builds (no overlaps, apertures within the spheres).
#include <random>
#include <sstream>

#include "prescription/LensSystem.h"

namespace lenslab::test {

inline LensSystem randomLens(std::mt19937_64& rng) {
    std::uniform_real_distribution<double> uni(0.0, 1.0);
    for (;;) {
        const int count = 2 + static_cast<int>(uni(rng) * 7);
        const int stopAt = static_cast<int>(uni(rng) * (count + 1));
        std::ostringstream table;
        table.precision(17);
        bool inGlass = false;
        for (int i = 0; i <= count; ++i) {
            const double gap = i == 0 ? 0.0 : 0.5 + 9.5 * uni(rng);
            if (i == stopAt && !inGlass) {
                table << "0 " << gap << " 0 " << 4 + 16 * uni(rng) << "\n";
                continue;
            }
            const double radius = uni(rng) < 0.1 ? 0.0 : (uni(rng) < 0.5 ? -1 : 1) * (15 + 185 * uni(rng));
            const bool last = i == count;
            inGlass = !last && !inGlass ? uni(rng) < 0.7 : (!last && uni(rng) < 0.3);
            const double n = inGlass ? 1.45 + 0.45 * uni(rng) : 1.0;
            const double maxD = radius == 0 ? 40.0 : std::min(40.0, 2 * std::fabs(radius));
            table << radius << " " << gap << " " << n << " " << (0.3 + 0.6 * uni(rng)) * maxD << "\n";
        }
        try {
            LensSystem lens = buildLensSystem(parseLensTable(table.str(), "random.dat"));
            return lens;
        } catch (const LensTableError&) {
            // Invalid draw (overlap, stop in glass, no stop): draw again.
        }
    }
}

}  // namespace lenslab::test
