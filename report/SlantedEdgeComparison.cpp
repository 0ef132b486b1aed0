#include "SlantedEdgeComparison.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "Render.h"
#include "analysis/LensDesignAnalysis.h"
#include "prescription/NumberText.h"

namespace lenslab {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kFrequencies = 41;  // 0 to the pixel Nyquist

double sinc(double x) { return x == 0 ? 1.0 : std::sin(kPi * x) / (kPi * x); }

// The film as the realistic camera maps it (RealisticCamera::filmPoint): raster x grows toward
// film -x, raster y toward film +y (the lens inverts the image).
struct Film {
    double halfWidthMm = 0.5 * kFilmDiagonalMm * kFilmWidthPixels / std::hypot(double(kFilmWidthPixels), double(kFilmHeightPixels));
    double halfHeightMm = 0.5 * kFilmDiagonalMm * kFilmHeightPixels / std::hypot(double(kFilmWidthPixels), double(kFilmHeightPixels));
    double pixelMm = kFilmDiagonalMm / std::hypot(double(kFilmWidthPixels), double(kFilmHeightPixels));
    double rasterX(double x) const { return 0.5 * kFilmWidthPixels * (1 - x / halfWidthMm); }
    double rasterY(double y) const { return 0.5 * kFilmHeightPixels * (1 + y / halfHeightMm); }
    double filmX(double rasterX) const { return -(2 * rasterX / kFilmWidthPixels - 1) * halfWidthMm; }
    double filmY(double rasterY) const { return (2 * rasterY / kFilmHeightPixels - 1) * halfHeightMm; }
};

LensSettings edgeSettings(const LensSystem& lens, const EdgeCase& c) {
    LensSettings s;
    if (c.fstop) s.fstop = Setting{*c.fstop, "slanted edge: f-number"};
    s.focusDistance = Setting{kChartDistanceMm, "slanted edge: the chart's distance"};
    if (lens.isDispersive()) s.wavelength = Setting{lens.primaryWavelength, "slanted edge: the primary wavelength"};
    return s;
}

RenderSettings edgeRender(const EdgeCase& c, const LensSettings& s, int x0, int y0) {
    RenderSettings r;
    r.scenePath = c.scenePath;
    r.camera.lensFile = c.lensPath;
    r.camera.fstop = s.fstop;
    r.camera.focusDistance = s.focusDistance;
    r.camera.wavelength = s.wavelength;
    r.camera.filmDiagonal = kFilmDiagonalMm;
    r.camera.mode = "exact";
    r.width = kFilmWidthPixels;
    r.height = kFilmHeightPixels;
    r.spp = c.spp;
    r.threads = c.threads;
    // A crop edge half a pixel inside pixel k rounds up to k (pbrt's ceil).
    r.crop = std::array<double, 4>{(x0 - 0.5) / kFilmWidthPixels, (x0 + c.cropPixels - 0.5) / kFilmWidthPixels,
                                   (y0 - 0.5) / kFilmHeightPixels, (y0 + c.cropPixels - 0.5) / kFilmHeightPixels};
    return r;
}

PixelRegion luminance(const Image& image) {
    PixelRegion r{image.width, image.height, {}};
    for (std::size_t k = 0; k + 2 < image.rgb.size(); k += 3)
        r.values.push_back((double(image.rgb[k]) + image.rgb[k + 1] + image.rgb[k + 2]) / 3);
    return r;
}

}  // namespace

EdgeComparison compareSlantedEdge(const EdgeCase& c) {
    if (c.chartStep < 0 || c.chartStep > kChartSteps || (c.chartStep == 0 && c.direction == MtfDirection::Sagittal))
        throw std::invalid_argument("slanted edge: the chart has tangential edges at steps 0-" + std::to_string(kChartSteps) +
                                    " and sagittal ones at 1-" + std::to_string(kChartSteps));
    const LensSystem lens = loadLensSystem(c.lensPath);
    const LensSettings settings = edgeSettings(lens, c);
    const LensAnalysis first = analyzeLens(lens, settings);

    // The edge's point on the chart, lens space: tangential edges above the axis, sagittal below.
    const double chartY = kChartDistanceMm * std::tan(c.chartStep * kChartStepDegrees * kPi / 180);
    EdgeComparison out;
    out.direction = c.direction;
    out.fieldDegrees = std::atan(chartY / (first.focus.objectZ - first.pupils.entrance.z)) * 180 / kPi;
    const Film film;
    out.pixelMm = film.pixelMm;

    DesignAnalysisInputs in;
    in.lens = settings;
    if (settings.wavelength) in.wavelengths = {settings.wavelength->value};
    in.fields = {out.fieldDegrees};
    in.fieldsInDegrees = true;
    in.maxFrequency = 0.5 / film.pixelMm;
    in.frequencies = kFrequencies;
    const LensDesignAnalysis analysis = analyzeLensDesign(lens, in);
    const FieldAnalysis& field = analysis.fields.front();
    if (!field.chiefImage) throw std::runtime_error("slanted edge: no ray of the " + formatNumber(out.fieldDegrees) + " degree field reaches the film");
    const Point2 chief = *field.chiefImage;
    out.fstop = analysis.lens.fstop;

    // The analysis's field lies toward +y and images toward -y; the sagittal edges lie below the axis.
    const double sign = c.direction == MtfDirection::Sagittal ? -1.0 : 1.0;
    const int x0 = int(std::lround(film.rasterX(chief.x))) - c.cropPixels / 2;
    const int y0 = int(std::lround(film.rasterY(sign * chief.y))) - c.cropPixels / 2;
    // The crop's window starts half a pixel before x0 (edgeRender), so x0 = 0 is off the film too.
    if (x0 < 1 || y0 < 1 || x0 + c.cropPixels > kFilmWidthPixels || y0 + c.cropPixels > kFilmHeightPixels)
        throw std::out_of_range("slanted edge: the chart's " + formatNumber(c.chartStep * kChartStepDegrees) +
                                " degree edge images off the film (chief ray at " + formatNumber(chief.y) + " mm)");
    std::vector<double> cycles;
    for (double nu : analysis.frequencies) cycles.push_back(nu * film.pixelMm);
    out.edge = slantedEdgeSfr(luminance(renderScene(edgeRender(c, settings, x0, y0)).image), cycles);

    out.filmX = film.filmX(x0 + out.edge.centreX);
    out.filmY = film.filmY(y0 + out.edge.centreY);
    const double offset = std::hypot(out.edge.centreX - 0.5 * c.cropPixels, out.edge.centreY - 0.5 * c.cropPixels);
    const double radius = std::hypot(out.filmX, out.filmY);
    // The normal's share along the film radius (raster axes: film -x, +y): near 1 across the radius.
    const double across = radius > 0 ? std::abs(-out.edge.normalX * out.filmX + out.edge.normalY * out.filmY) / radius : 1.0;
    const bool tangential = c.chartStep == 0 || across > std::sqrt(0.5);
    if (offset > 0.25 * c.cropPixels || tangential != (c.direction == MtfDirection::Tangential))
        throw std::runtime_error("slanted edge: the edge found in " + c.scenePath + " at film (" + formatNumber(out.filmX) + ", " +
                                 formatNumber(out.filmY) + ") mm is not the chart's " + formatNumber(c.chartStep * kChartStepDegrees) +
                                 " degree edge (report/SlantedEdgeComparison.h lays the chart out)");

    out.frequencies = analysis.frequencies;
    out.measured = out.edge.sfr;
    out.lens = c.direction == MtfDirection::Sagittal ? field.geometricSagittal : field.geometricTangential;
    for (std::size_t k = 0; k < cycles.size(); ++k) {
        out.pixel.push_back(sinc(cycles[k] * out.edge.normalX) * sinc(cycles[k] * out.edge.normalY));
        out.predicted.push_back(out.lens[k] * out.pixel[k]);
        if (cycles[k] <= 0.25 + 1e-12) out.maxDifference = std::max(out.maxDifference, std::abs(out.measured[k] - out.predicted[k]));
    }
    return out;
}

}  // namespace lenslab
