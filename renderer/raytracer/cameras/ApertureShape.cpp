#include "cameras/ApertureShape.h"

#include <cmath>
#include <stdexcept>

#include "ImageFileReader.h"

namespace lenslab {

namespace {

// `count` corners evenly around the centre, counter-clockwise from `startDegrees`, at radii taken
// from `radii` in turn.
std::vector<double> regularCorners(int count, double startDegrees, const std::vector<double>& radii) {
    std::vector<double> xy;
    for (int i = 0; i < count; ++i) {
        const double a = (startDegrees + 360.0 * i / count) * M_PI / 180;
        const double r = radii[i % radii.size()];
        xy.push_back(r * std::cos(a));
        xy.push_back(r * std::sin(a));
    }
    return xy;
}

double polygonArea(const std::vector<double>& xy) {
    double twice = 0;
    const std::size_t n = xy.size() / 2;
    for (std::size_t i = 0, j = n - 1; i < n; j = i++) twice += xy[2 * j] * xy[2 * i + 1] - xy[2 * i] * xy[2 * j + 1];
    return 0.5 * std::fabs(twice);
}

bool insidePolygon(const std::vector<double>& xy, double u, double v) {
    bool inside = false;  // even-odd rule: count the edges a ray toward +u crosses
    const std::size_t n = xy.size() / 2;
    for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
        const double xi = xy[2 * i], yi = xy[2 * i + 1], xj = xy[2 * j], yj = xy[2 * j + 1];
        if ((yi > v) != (yj > v) && u < xi + (v - yi) * (xj - xi) / (yj - yi)) inside = !inside;
    }
    return inside;
}

}  // namespace

bool ApertureShape::isNamed(const std::string& name) {
    return name == "circular" || name == "gaussian" || name == "square" || name == "pentagon" || name == "star";
}

ApertureShape ApertureShape::polygon(std::string name, std::vector<double> xy) {
    ApertureShape s;
    s.kind_ = Kind::Polygon;
    s.name_ = std::move(name);
    s.scale_ = M_PI / polygonArea(xy);
    s.xy_ = std::move(xy);
    return s;
}

ApertureShape ApertureShape::named(const std::string& name) {
    if (name == "circular") return {};
    if (name == "gaussian") {
        ApertureShape s;
        s.kind_ = Kind::Gaussian;
        s.name_ = name;
        // exp(-r^2) - exp(-1) integrates to pi (1 - 2/e) over the disc.
        s.scale_ = 1 / (1 - 2 / M_E);
        return s;
    }
    if (name == "square") return polygon(name, {-0.5, -0.5, 0.5, -0.5, 0.5, 0.5, -0.5, 0.5});
    if (name == "pentagon") return polygon(name, regularCorners(5, -90, {0.8}));
    if (name == "star") {
        // Inner corners where the lines between alternate outer ones cross: cos 72 / cos 36.
        const double inner = std::cos(72 * M_PI / 180) / std::cos(36 * M_PI / 180);
        return polygon(name, regularCorners(10, 0, {inner, 1.0}));
    }
    throw std::invalid_argument("unknown aperture shape \"" + name + "\"");
}

ApertureShape ApertureShape::fromImage(const std::string& path) {
    DecodedImage image;
    try {
        image = readImageFile(path);
    } catch (const std::runtime_error& e) {
        throw std::runtime_error("cannot read the aperture image '" + path + "': " + e.what());
    }
    const DecodedImage& spec = image;
    const std::vector<float>& all = image.pixels;
    ApertureShape s;
    s.kind_ = Kind::Image;
    s.name_ = path;
    s.width_ = spec.width;
    s.height_ = spec.height;
    const int colours = spec.channels >= 3 ? 3 : 1;  // an alpha channel is not light
    double sum = 0;
    for (std::size_t p = 0; p < std::size_t(spec.width) * spec.height; ++p) {
        float grey = 0;
        for (int c = 0; c < colours; ++c) grey += all[p * spec.channels + c];
        s.pixels_.push_back(std::max(0.0f, grey / colours));
        sum += s.pixels_.back();
    }
    if (!(sum > 0)) throw std::runtime_error("the aperture image '" + path + "' is black: it would pass no light");
    // The image spans the stop's bounding square (area 4); the circle covers pi of it.
    s.scale_ = (M_PI / 4) / (sum / s.pixels_.size());
    return s;
}

double ApertureShape::weight(double u, double v) const {
    const double r2 = u * u + v * v;
    if (r2 > 1) return 0;
    switch (kind_) {
        case Kind::Circular: return 1;
        case Kind::Gaussian: return scale_ * (std::exp(-r2) - std::exp(-1.0));
        case Kind::Polygon: return insidePolygon(xy_, u, v) ? scale_ : 0;
        case Kind::Image: {
            // Bilinear between pixel centres, black beyond the image's edge.
            const double fx = 0.5 * (u + 1) * width_ - 0.5, fy = 0.5 * (1 - v) * height_ - 0.5;
            const int x0 = int(std::floor(fx)), y0 = int(std::floor(fy));
            const double tx = fx - x0, ty = fy - y0;
            const auto texel = [&](int x, int y) {
                return x < 0 || y < 0 || x >= width_ || y >= height_ ? 0.0 : double(pixels_[std::size_t(y) * width_ + x]);
            };
            const double top = (1 - tx) * texel(x0, y0) + tx * texel(x0 + 1, y0);
            const double bottom = (1 - tx) * texel(x0, y0 + 1) + tx * texel(x0 + 1, y0 + 1);
            return scale_ * ((1 - ty) * top + ty * bottom);
        }
    }
    return 0;
}

}  // namespace lenslab
