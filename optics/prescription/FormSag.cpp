#include "prescription/FormSag.h"

namespace lenslab {

// Forbes 2010, appendix A: f_0 = 2, f_1 = sqrt(19) / 2, g_0 = -1/2, and for m >= 2
// h_{m-2} = -m (m - 1) / (2 f_{m-2}), g_{m-1} = -(1 + g_{m-2} h_{m-2}) / f_{m-1},
// f_m = sqrt(m (m + 1) + 3 - g_{m-1}^2 - h_{m-2}^2).
const QbfsRecurrence& qbfsRecurrence() {
    static const QbfsRecurrence r = [] {
        QbfsRecurrence q;
        q.f[0] = 2;
        q.f[1] = std::sqrt(19.0) / 2;
        q.g[0] = -0.5;
        for (int m = 2; m < kFormTerms; ++m) {
            q.h[m - 2] = -double(m) * (m - 1) / (2 * q.f[m - 2]);
            q.g[m - 1] = -(1 + q.g[m - 2] * q.h[m - 2]) / q.f[m - 1];
            q.f[m] = std::sqrt(double(m) * (m + 1) + 3 - q.g[m - 1] * q.g[m - 1] - q.h[m - 2] * q.h[m - 2]);
        }
        return q;
    }();
    return r;
}

}  // namespace lenslab
