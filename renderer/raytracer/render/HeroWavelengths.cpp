#include "render/HeroWavelengths.h"

#include <algorithm>
#include <cmath>

namespace lenslab {

namespace {

// One axis of the film: the rendered pixels [first, last] whose filter reaches coordinate x (pixel
// i centred at i + 0.5) and each one's filter there. Filters are separable and the rendered area a
// rectangle, so a pixel's filter at a point is the product of its two axes' values, and the
// density of film samples there from every rendered pixel the product of the axes' sums.
struct AxisReach {
    static constexpr int kMaxPixels = 32;  // a filter 31 pixels wide
    int first = 0, count = 0;
    double value[kMaxPixels] = {};  // h: the normalised filter (its density times its weight)
    double density = 0;             // the sum of the filter's sampling densities

    AxisReach(const PixelFilter& filter, bool alongX, double x, int areaFirst, int areaEnd) {
        const double radius = alongX ? filter.radiusX() : filter.radiusY();
        first = std::max(areaFirst, int(std::ceil(x - radius - 0.5)));
        const int last = std::min({areaEnd - 1, int(std::floor(x + radius - 0.5)), first + kMaxPixels - 1});
        for (int i = first; i <= last; ++i, ++count) {
            float w;
            const double offset = x - (i + 0.5);
            const double d = alongX ? filter.densityX(offset, w) : filter.densityY(offset, w);
            value[count] = d * w;
            density += d;
        }
    }
};

// Adds (h_P(landing) - h_P(own point)) * value to every rendered pixel P whose filter reaches either
// point: the own pixel's share into `own` (divided by its weight, as FilteredPixel multiplies it
// back), the others' times `scale` into `splats`.
void splatDifference(const AxisReach& lx, const AxisReach& ly, const AxisReach& ox, const AxisReach& oy, Vec3f value,
                     float scale, int px, int py, float ownWeight, Vec3f& own, SplatBuffer& splats) {
    const auto at = [](const AxisReach& a, int i) { return i >= a.first && i < a.first + a.count ? a.value[i - a.first] : 0.0; };
    const int x0 = std::min(lx.first, ox.first), x1 = std::max(lx.first + lx.count, ox.first + ox.count);
    const int y0 = std::min(ly.first, oy.first), y1 = std::max(ly.first + ly.count, oy.first + oy.count);
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) {
            const float h = float(at(lx, x) * at(ly, y) - at(ox, x) * at(oy, y));
            if (h == 0) continue;
            if (x == px && y == py) own += (h / ownWeight) * value;
            else splats.add(x, y, (scale * h) * value);
        }
}

}  // namespace

Vec3f heroWavelengthEstimate(const SpectralSensor& sensor, const PixelFilter& filter, const PixelRect& area, int px,
                             int py, float ownWeight, const Vec3f& radiance, const WavelengthSample* wavelengths,
                             const FilmLanding* landings, int count, float splatScale, SplatBuffer& splats) {
    double filmDensity[kMaxWavelengthsPerSample], sum = 0;
    for (int k = 0; k < count; ++k) {
        const FilmLanding& l = landings[k];
        const bool atHero = k > 0 && l.rasterX == landings[0].rasterX && l.rasterY == landings[0].rasterY;
        filmDensity[k] = !(l.density > 0) ? 0.0
                         : atHero         ? filmDensity[0]
                                          : AxisReach(filter, true, l.rasterX, area.x0, area.x1).density *
                                                AxisReach(filter, false, l.rasterY, area.y0, area.y1).density;
        sum += filmDensity[k] * l.density;
    }
    Vec3f own;
    if (!(sum > 0) || ownWeight == 0) return own;
    const std::array<float, kSmitsBases> spectrum = smitsCoefficients(radiance);
    const FilmLanding& hero = landings[0];
    const AxisReach heroX(filter, true, hero.rasterX, area.x0, area.x1), heroY(filter, false, hero.rasterY, area.y0, area.y1);
    for (int k = 0; k < count; ++k) {
        const FilmLanding& l = landings[k];
        if (!(filmDensity[k] > 0) || !(l.response > 0)) continue;
        const Vec3f value = float(l.response / sum) * sensor.toRgb(spectrum, wavelengths[k]);
        // Carried with the sample, as its own film point's filter would weigh it.
        own += float(filmDensity[0]) * value;
        if (l.rasterX == hero.rasterX && l.rasterY == hero.rasterY) continue;
        // The difference between where it landed and the sample's own point.
        splatDifference(AxisReach(filter, true, l.rasterX, area.x0, area.x1),
                        AxisReach(filter, false, l.rasterY, area.y0, area.y1), heroX, heroY, value, splatScale, px, py,
                        ownWeight, own, splats);
    }
    return own;
}

}  // namespace lenslab
