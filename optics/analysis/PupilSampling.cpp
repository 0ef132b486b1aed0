#include "analysis/PupilSampling.h"

#include <cmath>
#include <stdexcept>

namespace lenslab {

std::vector<Point2> pupilPoints(PupilPattern pattern, int rings) {
    if (rings < 1 || rings > 64) throw std::invalid_argument("pupil sampling: rings must lie between 1 and 64");
    constexpr double kPi = 3.14159265358979323846;
    std::vector<Point2> points;
    if (pattern == PupilPattern::Hexapolar) {
        points.push_back({0, 0});
        for (int k = 1; k <= rings; ++k) {
            const double r = double(k) / rings;
            for (int j = 0; j < 6 * k; ++j) {
                const double a = 2 * kPi * j / (6 * k);
                points.push_back({r * std::sin(a), r * std::cos(a)});  // from +y, the tangential rim
            }
        }
        return points;
    }
    for (int j = -rings; j <= rings; ++j)
        for (int i = -rings; i <= rings; ++i) {
            const double x = double(i) / rings, y = double(j) / rings;
            if (x * x + y * y <= 1 + 1e-12) points.push_back({x, y});
        }
    return points;
}

}  // namespace lenslab
