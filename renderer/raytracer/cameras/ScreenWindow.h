#pragma once
// pbrt-v3's screen window: raster pixels (y down) to screen coordinates (y up) spanning [-1, 1] on
// the shorter image side, or the window a scene gives with "screenwindow" [x0 x1 y0 y1].
#include <array>

namespace lenslab {

struct ScreenWindow {
    double x0, x1, y0, y1;

    static ScreenWindow forImage(int width, int height) {
        const double aspect = double(width) / height;
        return aspect > 1 ? ScreenWindow{-aspect, aspect, -1, 1} : ScreenWindow{-1, 1, -1 / aspect, 1 / aspect};
    }
    void toScreen(double rasterX, double rasterY, int width, int height, double& sx, double& sy) const {
        sx = x0 + (x1 - x0) * rasterX / width;
        sy = y1 - (y1 - y0) * rasterY / height;
    }
};

}  // namespace lenslab
