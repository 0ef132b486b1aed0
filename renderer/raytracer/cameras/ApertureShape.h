#pragma once
// The shape of the aperture stop's opening, pbrt-v4's "aperture": a weight over the stop in units of
// its radius (u, v: lens-space x and y divided by the stop radius), 0 where the diaphragm blocks.
// Every shape passes as much light as the plain circle (pbrt-v4 normalises its aperture images the
// same way), so changing the shape changes the bokeh, not the exposure. The outlines follow
// pbrt-v4's built-in images, drawn exactly instead of rasterised: square of half the stop's width,
// pentagon inscribed in 0.8 of it with a corner toward -y, five-pointed star touching the rim.
#include <string>
#include <vector>

namespace lenslab {

class ApertureShape {
public:
    ApertureShape() = default;  // circular: the stop's own disc

    // circular | gaussian | square | pentagon | star. Throws std::invalid_argument for other names.
    static ApertureShape named(const std::string& name);
    // A grey (or RGB, averaged) image spanning the stop's bounding square, top row at +v.
    // Throws std::runtime_error when the file cannot be read or holds no light.
    static ApertureShape fromImage(const std::string& path);
    static bool isNamed(const std::string& name);

    bool isCircular() const { return kind_ == Kind::Circular; }
    const std::string& name() const { return name_; }
    double weight(double u, double v) const;

private:
    enum class Kind { Circular, Gaussian, Polygon, Image };
    static ApertureShape polygon(std::string name, std::vector<double> xy);

    Kind kind_ = Kind::Circular;
    std::string name_ = "circular";
    double scale_ = 1;            // the normalisation to the circle's throughput
    std::vector<double> xy_;      // polygon corners x0 y0 x1 y1 ...
    int width_ = 0, height_ = 0;  // image
    std::vector<float> pixels_;
};

}  // namespace lenslab
