#include "analysis/PupilSampling.h"

#include <cmath>
#include <stdexcept>
#include <utility>

#include "prescription/Pi.h"

namespace lenslab {

namespace {

// The Gauss-Legendre nodes and weights of order n on [-1, 1]: the roots of P_n by Newton's method from
// Tricomi's estimate, weights 2 / ((1 - x^2) P_n'(x)^2).
std::vector<std::pair<double, double>> gaussLegendre(int n) {
    std::vector<std::pair<double, double>> nodes;
    for (int i = 1; i <= n; ++i) {
        double x = std::cos(kPi * (i - 0.25) / (n + 0.5)), derivative = 1;
        for (int it = 0; it < 100; ++it) {
            double p0 = 1, p1 = x;  // P_0, P_1, then the three-term recurrence up to P_n
            for (int k = 2; k <= n; ++k) {
                const double p2 = ((2 * k - 1) * x * p1 - (k - 1) * p0) / k;
                p0 = p1, p1 = p2;
            }
            derivative = n * (x * p1 - p0) / (x * x - 1);
            const double step = p1 / derivative;
            x -= step;
            if (std::fabs(step) <= 1e-16) break;
        }
        nodes.push_back({x, 2 / ((1 - x * x) * derivative * derivative)});
    }
    return nodes;
}

}  // namespace

std::vector<std::pair<double, double>> gaussLegendreUnit(int n) {
    if (n < 1 || n > 256) throw std::invalid_argument("pupil sampling: 1-256 Gauss-Legendre nodes");
    std::vector<std::pair<double, double>> unit;
    for (const auto& [x, w] : gaussLegendre(n)) unit.push_back({0.5 * (1 - x), 0.5 * w});
    return unit;
}

Point2 azimuthDirection(int k, int n) {
    const double phi = 2 * kPi * k / n;
    return {std::sin(phi), std::cos(phi)};
}

}  // namespace lenslab
