#include "core/ColourMatching.h"

#include <cmath>

namespace lenslab {

namespace {

double lobe(double x, double mu, double sigmaBelow, double sigmaAbove) {
    const double t = (x - mu) / (x < mu ? sigmaBelow : sigmaAbove);
    return std::exp(-0.5 * t * t);
}

}  // namespace

double cieX(double l) {
    return 1.056 * lobe(l, 599.8, 37.9, 31.0) + 0.362 * lobe(l, 442.0, 16.0, 26.7) - 0.065 * lobe(l, 501.1, 20.4, 26.2);
}
double cieY(double l) { return 0.821 * lobe(l, 568.8, 46.9, 40.5) + 0.286 * lobe(l, 530.9, 16.3, 31.1); }
double cieZ(double l) { return 1.217 * lobe(l, 437.0, 11.8, 36.0) + 0.681 * lobe(l, 459.0, 26.0, 13.8); }

double cieYIntegral() {
    static const double integral = [] {
        double s = 0;
        for (int l = kVisibleFirstNm; l <= kVisibleLastNm; ++l) s += cieY(l);
        return s;
    }();
    return integral;
}

}  // namespace lenslab
