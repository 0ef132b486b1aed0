#include "analysis/GeometricMtf.h"

#include <cmath>
#include <complex>

namespace lenslab {

std::vector<double> geometricMtf(const std::vector<SpotDiagram>& spots, const std::vector<double>& weights,
                                 MtfDirection direction, const std::vector<double>& frequencies) {
    constexpr double kTwoPi = 6.28318530717958647692;
    std::vector<double> mtf;
    for (double nu : frequencies) {
        std::complex<double> sum = 0;
        double total = 0;
        for (std::size_t j = 0; j < spots.size(); ++j) {
            for (std::size_t k = 0; k < spots[j].points.size(); ++k) {
                const Point2& p = spots[j].points[k];
                const double w = weights[j] * spots[j].weights[k];
                const double u = direction == MtfDirection::Sagittal ? p.x : p.y;
                sum += w * std::polar(1.0, kTwoPi * nu * u);
                total += w;
            }
        }
        mtf.push_back(total > 0 ? std::abs(sum) / total : 0.0);
    }
    return mtf;
}

}  // namespace lenslab
