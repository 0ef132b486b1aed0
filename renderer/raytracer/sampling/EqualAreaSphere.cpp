#include "sampling/EqualAreaSphere.h"

#include <algorithm>
#include <cmath>

namespace lenslab {

// The square, as [-1, 1]^2, folds onto the octahedron |x| + |y| + |z| = 1: the diamond inside
// |u| + |v| = 1 is the upper hemisphere. r, the distance from the diamond's edge, sets the polar
// angle (1 - r^2 = cos theta keeps areas), and the position along the edge of the square ring of
// radius r sets phi within its quadrant.
Vec3f equalAreaSquareToSphere(float u, float v) {
    const float x = 2 * u - 1, y = 2 * v - 1;
    const float ax = std::abs(x), ay = std::abs(y);
    const float signedDistance = 1 - (ax + ay);
    const float r = 1 - std::abs(signedDistance);
    const float phi = (r == 0 ? 1 : (ay - ax) / r + 1) * float(M_PI) / 4;
    const float z = std::copysign(1 - r * r, signedDistance);
    const float ring = r * std::sqrt(std::max(0.0f, 2 - r * r));
    return {std::copysign(std::cos(phi), x) * ring, std::copysign(std::sin(phi), y) * ring, z};
}

void equalAreaSphereToSquare(Vec3f d, float& u, float& v) {
    const float ax = std::abs(d.x), ay = std::abs(d.y), az = std::min(1.0f, std::abs(d.z));
    const float r = std::sqrt(1 - az);  // inverts z = 1 - r^2
    // phi within the quadrant, 0 along x, pi/2 along y; its share of the quadrant runs along the ring.
    const float phi = (ax == 0 && ay == 0) ? 0 : std::atan2(ay, ax);
    const float share = phi / (float(M_PI) / 2);
    float y = share * r, x = r - y;
    if (d.z < 0) {  // the lower hemisphere lies in the corners, mirrored across the diamond's edge
        const float t = x;
        x = 1 - y;
        y = 1 - t;
    }
    x = std::copysign(x, d.x);
    y = std::copysign(y, d.y);
    u = std::clamp(0.5f * (x + 1), 0.0f, 1.0f);
    v = std::clamp(0.5f * (y + 1), 0.0f, 1.0f);
}

}  // namespace lenslab
