#pragma once
// pbrt-v4's camera sensor (Film "string sensor" naming a measured camera, core/CameraSensorCurves.h)
// applied to lenslab's RGB radiance.
//
// pbrt-v4 integrates each sample's spectrum against the camera's r, g, b curves and maps that
// sensor RGB to XYZ by a 3 x 3 matrix fitted by least squares over the 24 ColorChecker swatches:
// lit by the sensor's illuminant (daylight at the white balance temperature) they should come out
// as their XYZ under D65, at the illuminant's luminance. That fit is the white balance, and its
// residual the camera's colour error.
//
// lenslab's radiance is the CIE observer's linear sRGB. For an RGB scene pbrt-v4's spectra are
// smooth shapes times D65 (its sRGB lights are D65 times a sigmoid, reflectances sigmoids), so the
// film takes each pixel's colour as D65 times the Smits spectrum (core/SmitsSpectrum.h) whose CIE
// colour it is, and records what the camera makes of that. Smits is linear within each ordering of
// the channels, so this is a piecewise linear map, found from the camera's response to each
// basis spectrum. It stands in for pbrt-v4's own upsampling (its sigmoids), which lenslab does not
// render; docs/pbrt-v4.md gives the difference this leaves.
#include <array>
#include <functional>

#include "core/CameraSensorCurves.h"
#include "core/Matrix3.h"
#include "core/SmitsSpectrum.h"
#include "core/Vec3f.h"

namespace lenslab {

class MeasuredCameraSensor {
public:
    MeasuredCameraSensor(const CameraSensorCurves& curves, double whiteBalanceKelvin);

    // The sensor's raw r, g, b for a spectrum: each curve times it, summed at every whole nm from
    // 360 to 830 (pbrt-v4's range; the curves' end values held beyond their 380-720 nm).
    Triple sensorRgb(const std::function<double(double)>& spectrum) const;
    // pbrt-v4's XYZFromSensorRGB: the least-squares fit described above.
    const Matrix3& xyzFromSensorRgb() const { return xyzFromSensorRgb_; }
    // The light that lit the training swatches: pbrt-v4's temperature-to-CCT rescaling
    // (x 1.4388 / 1.4380) of the white balance, CIE daylight at that CCT, a black body below 4000 K.
    double illuminant(double nm) const;

    // A pixel's linear sRGB (D65 white) as this camera, white balanced, records it.
    Vec3f toFilm(const Vec3f& rgb) const;

private:
    CameraSensorCurves curves_;
    double illuminantCct_;
    Matrix3 xyzFromSensorRgb_;
    // Per Smits basis spectrum times D65: its CIE linear sRGB, and the film's sRGB through this
    // camera, both per unit luminance of D65.
    std::array<Vec3f, kSmitsBases> cieOfBasis_, filmOfBasis_;
};

}  // namespace lenslab
