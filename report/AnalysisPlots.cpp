#include "AnalysisPlots.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <tuple>

#include "AnalysisTables.h"
#include "prescription/NumberText.h"
#include "SvgPlot.h"

namespace lenslab {

namespace {

// A spot plot draws every ray up to this many per wavelength, else every k-th: more dots than a
// plot's 280-pixel square shows only weigh on the page.
constexpr std::size_t kMaxDrawnSpotPoints = 1000;
// The plots of a field side by side in a row of the page, each readable on a phone (390 px) alone.
constexpr int kFieldPlotWidth = 360, kFieldPlotHeight = 300;
// A spot plot's area square: its width less the axis margins, plus the title and axis bands.
constexpr int kSpotPlotHeight = 354;
// The polychromatic MTF: diffraction and geometric in one colour each, the limit distinct.
const char* const kDiffractionColour = "#000000";
const char* const kGeometricColour = "#cc79a7";
const char* const kLimitColour = "#7f7f7f";
const char* const kSectionColour = "#555555";  // the legend's T and S keys: line style only

Plot makePlot(const std::string& id, const std::string& title, const std::string& xLabel, const std::string& yLabel) {
    Plot p;
    p.id = id;
    p.title = title;
    p.x.label = xLabel;
    p.y.label = yLabel;
    p.width = kFieldPlotWidth;
    p.height = kFieldPlotHeight;
    return p;
}

PlotSeries makeSeries(const std::string& label, const std::string& colour, LineDash dash = LineDash::Solid,
                      SeriesStyle style = SeriesStyle::Line) {
    PlotSeries s;
    s.label = label;
    s.colour = colour;
    s.dash = dash;
    s.style = style;
    return s;
}

PlotSeries curve(const std::string& label, const std::string& colour, const std::vector<double>& x, const std::vector<double>& y,
                 LineDash dash = LineDash::Solid) {
    PlotSeries s = makeSeries(label, colour, dash);
    s.x = x;
    s.y = y;
    return s;
}

std::string nm(double wavelength) { return formatFixed(wavelength, 1) + " nm"; }
std::string fieldName(const FieldAnalysis& f) { return formatFixed(f.fieldDegrees, 1) + "\u00b0"; }
std::string wavelengthList(const LensDesignAnalysis& a) {
    std::string list;
    for (double w : a.wavelengths) list += (list.empty() ? "" : ", ") + formatFixed(w, 1);
    return list + " nm";
}

const char* const kBlocked = kNotImagedWhy;

// A colour key per wavelength and a line-style key per section: tangential solid, sagittal dashed.
std::vector<PlotSeries> wavelengthAndSectionLegend(const std::vector<double>& wavelengths) {
    std::vector<PlotSeries> legend;
    for (double w : wavelengths) legend.push_back(makeSeries(nm(w), wavelengthColour(w)));
    legend.push_back(makeSeries("T", kSectionColour));
    legend.push_back(makeSeries("S", kSectionColour, LineDash::Dashed));
    return legend;
}

std::string referenceWords(const LensDesignAnalysis& a) {
    return a.reference == SpotReference::ChiefRay ? "the chief ray" : "the centroid";
}

Plot spotPlot(const LensDesignAnalysis& a, std::size_t field, const std::string& id) {
    const FieldAnalysis& f = a.fields[field];
    Plot p = makePlot(id, "Spot diagram, " + fieldName(f) + ", about " + referenceWords(a), "x (\u00b5m)", "y (\u00b5m)");
    p.height = kSpotPlotHeight;
    double extent = 0;
    for (std::size_t j = 0; j < f.spots.size(); ++j) {
        const SpotDiagram& s = f.spots[j];
        PlotSeries series = makeSeries("", wavelengthColour(s.wavelength), LineDash::Solid, SeriesStyle::Markers);
        series.markerRadius = 1.2;
        const std::size_t step = (s.points.size() + kMaxDrawnSpotPoints - 1) / kMaxDrawnSpotPoints;
        for (std::size_t k = 0; k < s.points.size(); k += std::max<std::size_t>(step, 1)) {
            const Point2& q = s.points[k];
            series.x.push_back(q.x * kUm);
            series.y.push_back(q.y * kUm);
        }
        for (const Point2& q : s.points) extent = std::max({extent, std::fabs(q.x * kUm), std::fabs(q.y * kUm)});
        p.series.push_back(series);
        // The legend names each wavelength's RMS radius as the tables show it (the same cell).
        const ShownValue rms = spotRmsShown(a, field, j);
        PlotSeries key = makeSeries(nm(s.wavelength) + ": RMS " + rms.text + (s.points.empty() ? "" : " \u00b5m"),
                                    series.colour, LineDash::Solid, SeriesStyle::Markers);
        key.labelAttributes = shownValueAttributes(rms);
        p.legend.push_back(key);
    }
    if (!f.traced) p.note = kBlocked;
    // Square and centred on the field's reference point, so the spot's shape is not stretched.
    extent = extent > 0 ? extent * 1.05 : 1;
    p.x.min = p.y.min = -extent;
    p.x.max = p.y.max = extent;
    return p;
}

Plot mtfPlot(const LensDesignAnalysis& a, const FieldAnalysis& f, const std::string& id) {
    Plot p = makePlot(id, "MTF, " + fieldName(f) + ", polychromatic", "spatial frequency (lp/mm)", "modulation");
    p.y.min = 0;
    p.y.max = 1;
    p.x.min = 0;
    p.x.max = a.frequencies.empty() ? 1 : a.frequencies.back();
    p.series = {curve("", kLimitColour, a.frequencies, a.diffractionLimit, LineDash::Dotted)};
    if (f.traced)
        for (const auto& [colour, tangential, sagittal] :
             {std::tuple(kDiffractionColour, &f.diffractionTangential, &f.diffractionSagittal),
              std::tuple(kGeometricColour, &f.geometricTangential, &f.geometricSagittal)}) {
            p.series.push_back(curve("", colour, a.frequencies, *tangential));
            p.series.push_back(curve("", colour, a.frequencies, *sagittal, LineDash::Dashed));
        }
    else
        p.note = kBlocked;
    p.legend = {makeSeries("diffraction", kDiffractionColour), makeSeries("geometric", kGeometricColour),
                makeSeries(a.obscuration > 0 ? "obscured limit" : "diffraction limit", kLimitColour, LineDash::Dotted),
                makeSeries("T", kSectionColour), makeSeries("S", kSectionColour, LineDash::Dashed)};
    return p;
}

Plot fanPlot(const LensDesignAnalysis& a, const FieldAnalysis& f, const std::string& id) {
    Plot p = makePlot(id, "Ray fans, " + fieldName(f) + ", from the chief ray", "pupil coordinate", "ray error (\u00b5m)");
    p.x.min = -1;  // the whole pupil, where a vignetted or obscured part has no rays
    p.x.max = 1;
    for (const RayFan& fan : f.fans)
        for (bool tangential : {true, false}) {
            PlotSeries s = makeSeries("", wavelengthColour(fan.wavelength), tangential ? LineDash::Solid : LineDash::Dashed);
            s.x = fan.pupil;
            for (double e : tangential ? fan.tangential : fan.sagittal) s.y.push_back(e * kUm);
            p.series.push_back(s);
        }
    if (!f.traced) p.note = kBlocked;
    p.legend = wavelengthAndSectionLegend(a.wavelengths);
    return p;
}

Plot fieldCurvaturePlot(const LensDesignAnalysis& a) {
    Plot p = makePlot("field-curvature", "Field curvature", "focus from the image plane (mm)", "field (\u00b0)");
    for (std::size_t j = 0; j < a.fieldCurvature.size(); ++j)
        for (bool tangential : {true, false}) {
            PlotSeries s = makeSeries("", wavelengthColour(a.wavelengths[j]), tangential ? LineDash::Solid : LineDash::Dashed);
            for (const FieldCurvatureSample& c : a.fieldCurvature[j]) {
                s.x.push_back(c.found ? (tangential ? c.tangentialShift : c.sagittalShift) : NAN);
                s.y.push_back(c.fieldDegrees);
            }
            p.series.push_back(s);
        }
    p.legend = wavelengthAndSectionLegend(a.wavelengths);
    return p;
}

Plot distortionPlot(const LensDesignAnalysis& a) {
    Plot p = makePlot("distortion", "Distortion at " + nm(a.primaryWavelength), "distortion (%)", "field (\u00b0)");
    PlotSeries s = makeSeries("distortion", wavelengthColour(a.primaryWavelength));
    for (const DistortionSample& d : a.distortion) {
        s.x.push_back(d.found ? d.distortionPercent : NAN);
        s.y.push_back(d.fieldDegrees);
    }
    p.series.push_back(s);
    return p;
}

Plot illuminationPlot(const LensDesignAnalysis& a) {
    Plot p = makePlot("relative-illumination", "Relative illumination at " + nm(a.primaryWavelength), "film radius (mm)",
                      "relative illumination");
    p.y.min = 0;
    p.y.max = 1.05;
    PlotSeries s = makeSeries("relative illumination", wavelengthColour(a.primaryWavelength));
    for (const IlluminationSample& i : a.illumination) {
        s.x.push_back(i.filmRadius);
        s.y.push_back(i.relativeIllumination);
    }
    p.series.push_back(s);
    if (a.illumination.empty()) p.note = "not measured: no ray found from the film";
    return p;
}

Plot focalShiftPlot(const LensDesignAnalysis& a) {
    Plot p = makePlot("chromatic-focal-shift", "Chromatic focal shift (paraxial)", "focus from the d line (mm)", "wavelength (nm)");
    PlotSeries spectrum = makeSeries("paraxial focus", kSectionColour);
    for (const FocalShiftSample& f : a.focalShiftSpectrum) {
        spectrum.x.push_back(f.shift);
        spectrum.y.push_back(f.wavelength);
    }
    p.series = {spectrum};
    for (const FocalShiftSample& f : a.focalShift) {
        PlotSeries chosen = makeSeries(nm(f.wavelength), wavelengthColour(f.wavelength), LineDash::Solid, SeriesStyle::Markers);
        chosen.x = {f.shift};
        chosen.y = {f.wavelength};
        p.series.push_back(chosen);
    }
    return p;
}

NamedSvg named(const std::string& name, const std::string& caption, const Plot& plot) { return {name, caption, svgPlot(plot)}; }

// Linear in sRGB between colours at given wavelengths, held beyond the ends.
struct ColourStop {
    double nm;
    int r, g, b;
};
const ColourStop kWavelengthColours[] = {
    {400, 0x7b, 0x32, 0x94},        // violet
    {kWavelengthF, 0x00, 0x72, 0xb2},  // blue
    {kWavelengthD, 0x00, 0x9e, 0x73},  // bluish green
    {kWavelengthC, 0xd5, 0x5e, 0x00},  // vermilion
    {760, 0x8b, 0x1a, 0x1a},        // dark red
};

}  // namespace

std::string wavelengthColour(double w) {
    const ColourStop* lo = std::begin(kWavelengthColours);
    const ColourStop* hi = lo;
    for (const ColourStop& s : kWavelengthColours)
        if (s.nm <= w) lo = hi = &s;
        else {
            hi = &s;
            break;
        }
    const double t = hi->nm > lo->nm ? (w - lo->nm) / (hi->nm - lo->nm) : 0;
    const auto mix = [t](int a, int b) { return static_cast<int>(std::lround(a + t * (b - a))); };
    char hex[8];
    std::snprintf(hex, sizeof hex, "#%02x%02x%02x", mix(lo->r, hi->r), mix(lo->g, hi->g), mix(lo->b, hi->b));
    return hex;
}

std::vector<NamedSvg> designAnalysisPlots(const LensDesignAnalysis& a, bool curves) {
    std::vector<NamedSvg> plots;
    const std::string reference = a.reference == SpotReference::ChiefRay ? "the primary wavelength's chief ray" : "the polychromatic centroid";
    for (std::size_t i = 0; i < a.fields.size(); ++i) {
        const FieldAnalysis& f = a.fields[i];
        const std::string suffix = "field-" + std::to_string(i + 1), at = fieldName(f);
        const std::string blocked = f.traced ? "" : std::string(" This field is ") + kNotImagedWhy + ".";
        plots.push_back(named("spot-" + suffix,
                              "Spot diagram at " + at + " (" + wavelengthList(a) + "): ray hits on the image plane about " +
                                  reference + "; RMS radii about " + referenceWords(a) + "." + blocked,
                              spotPlot(a, i, "spot-" + suffix)));
        plots.push_back(named("mtf-" + suffix,
                              "MTF at " + at + ", polychromatic: tangential (T, solid) and sagittal (S, dashed), from the pupil "
                                  "(diffraction) and the spot (geometric), with the " +
                                  (a.obscuration > 0 ? "obscured pupil's diffraction limit." : "diffraction limit.") + blocked,
                              mtfPlot(a, f, "mtf-" + suffix)));
        plots.push_back(named("fans-" + suffix,
                              "Ray fans at " + at + ": transverse ray error from the primary chief ray against pupil coordinate, "
                                  "tangential (solid) and sagittal (dashed), a colour per wavelength; blocked rays are gaps." +
                                  blocked,
                              fanPlot(a, f, "fans-" + suffix)));
    }
    if (curves && a.largestFieldDegrees) {  // the curves run from the axis to the largest field
        plots.push_back(named("field-curvature",
                              "Field curvature: tangential (solid) and sagittal (dashed) focus against field, from the image "
                              "plane (+ toward the lens), a colour per wavelength.",
                              fieldCurvaturePlot(a)));
        plots.push_back(named("distortion", "Distortion against field: the chief ray's height on the F\u2032 plane against f tan \u03b8.",
                              distortionPlot(a)));
        plots.push_back(named("relative-illumination",
                              "Relative illumination against image height on the image plane, 1 on the axis (cos\u2074 included).",
                              illuminationPlot(a)));
    }
    plots.push_back(named("chromatic-focal-shift",
                          "Chromatic focal shift: the paraxial focus against wavelength, from the d line's (+ toward the lens); "
                          "the analysis's wavelengths marked.",
                          focalShiftPlot(a)));
    return plots;
}

}  // namespace lenslab
