#include "film/Demosaic.h"

#include <stdexcept>

namespace lenslab {

namespace {

// An index mirrored about the first and the last site, without repeating them: its parity, and so
// its filter colour, stays that of the site it stands for.
int mirrored(int i, int n) {
    while (i < 0 || i >= n) i = i < 0 ? -i : 2 * (n - 1) - i;
    return i;
}

}  // namespace

Image demosaic(const std::vector<float>& sites, int width, int height, const BayerPattern& pattern) {
    if (width < 2 || height < 2 || sites.size() != std::size_t(width) * std::size_t(height))
        throw std::invalid_argument("demosaic: a Bayer mosaic needs 2 x 2 sites at least, and one value a site");
    Image image;
    image.width = width;
    image.height = height;
    image.rgb.resize(sites.size() * 3);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const auto v = [&](int dx, int dy) {
                return double(sites[std::size_t(mirrored(y + dy, height)) * width + std::size_t(mirrored(x + dx, width))]);
            };
            const double centre = v(0, 0);
            const double sides = v(-1, 0) + v(1, 0) + v(0, -1) + v(0, 1);
            const double corners = v(-1, -1) + v(1, -1) + v(-1, 1) + v(1, 1);
            const double farAcross = v(-2, 0) + v(2, 0), farAlong = v(0, -2) + v(0, 2), far = farAcross + farAlong;
            const int own = pattern.channelAt(x, y);
            float* out = &image.rgb[(std::size_t(y) * width + x) * 3];
            out[own] = float(centre);
            if (own == 1) {
                // A green site: the colour of its row from its left and right, its column's from above and below.
                const double fromRow = (5 * centre + 4 * (v(-1, 0) + v(1, 0)) - farAcross - corners + 0.5 * farAlong) / 8;
                const double fromColumn = (5 * centre + 4 * (v(0, -1) + v(0, 1)) - farAlong - corners + 0.5 * farAcross) / 8;
                out[pattern.channelAt(x + 1, y)] = float(fromRow);
                out[pattern.channelAt(x, y + 1)] = float(fromColumn);
            } else {
                // A red or blue site: green from its sides, the other colour from its corners.
                out[1] = float((4 * centre + 2 * sides - far) / 8);
                out[2 - own] = float((6 * centre + 2 * corners - 1.5 * far) / 8);
            }
        }
    return image;
}

}  // namespace lenslab
