#include "AnalysisPlots.h"

#include <algorithm>
#include <cmath>

#include "prescription/NumberText.h"
#include "SvgPlot.h"

namespace lenslab {

namespace {

constexpr double kUm = 1000;  // spot and fan plots in micrometres: the sizes designers read

Plot makePlot(const std::string& id, const std::string& title, const std::string& xLabel, const std::string& yLabel) {
    Plot p;
    p.id = id;
    p.title = title;
    p.x.label = xLabel;
    p.y.label = yLabel;
    return p;
}

PlotSeries makeSeries(const std::string& label, SeriesStyle style = SeriesStyle::Line, bool dashed = false) {
    PlotSeries s;
    s.label = label;
    s.style = style;
    s.dashed = dashed;
    return s;
}

PlotSeries curve(const std::string& label, const std::vector<double>& x, const std::vector<double>& y, bool dashed = false) {
    PlotSeries s = makeSeries(label, SeriesStyle::Line, dashed);
    s.x = x;
    s.y = y;
    return s;
}

std::string nm(double wavelength) { return formatNumber(wavelength, 4) + " nm"; }
std::string fieldName(const FieldAnalysis& f) { return formatNumber(f.fieldDegrees, 3) + "\u00b0"; }

Plot spotPlot(const FieldAnalysis& f, const std::string& id) {
    Plot p = makePlot(id, "Spot diagram, field " + fieldName(f), "x (\u00b5m)", "y (\u00b5m)");
    p.width = 360;
    p.height = 380;
    double extent = 0;
    for (const SpotDiagram& s : f.spots) {
        PlotSeries series = makeSeries(nm(s.wavelength) + ", RMS " + formatNumber(s.statistics.rmsRadius * kUm, 3) + " \u00b5m",
                                       SeriesStyle::Markers);
        series.markerRadius = 1.2;
        for (const Point2& q : s.points) {
            series.x.push_back(q.x * kUm);
            series.y.push_back(q.y * kUm);
            extent = std::max({extent, std::fabs(q.x * kUm), std::fabs(q.y * kUm)});
        }
        p.series.push_back(series);
    }
    // Square and centred on the field's reference point, so the spot's shape is not stretched.
    extent = extent > 0 ? extent * 1.05 : 1;
    p.x.min = p.y.min = -extent;
    p.x.max = p.y.max = extent;
    return p;
}

Plot mtfPlot(const LensDesignAnalysis& a, const FieldAnalysis& f, const std::string& id) {
    Plot p = makePlot(id, "MTF, field " + fieldName(f), "spatial frequency (lp/mm)", "modulation");
    p.y.min = 0;
    p.y.max = 1;
    p.series = {curve("diffraction limit", a.frequencies, a.diffractionLimit, true),
                curve("diffraction T", a.frequencies, f.diffractionTangential),
                curve("diffraction S", a.frequencies, f.diffractionSagittal),
                curve("geometric T", a.frequencies, f.geometricTangential, true),
                curve("geometric S", a.frequencies, f.geometricSagittal, true)};
    return p;
}

Plot fanPlot(const FieldAnalysis& f, const std::string& id) {
    Plot p = makePlot(id, "Ray fans, field " + fieldName(f), "normalised pupil coordinate", "ray error (\u00b5m)");
    for (const RayFan& fan : f.fans)
        for (bool tangential : {true, false}) {
            PlotSeries s = makeSeries((tangential ? "T " : "S ") + nm(fan.wavelength), SeriesStyle::Line, !tangential);
            s.x = fan.pupil;
            for (double e : tangential ? fan.tangential : fan.sagittal) s.y.push_back(e * kUm);
            p.series.push_back(s);
        }
    return p;
}

Plot fieldCurvaturePlot(const LensDesignAnalysis& a) {
    Plot p = makePlot("field-curvature", "Field curvature", "focus shift from the image plane (mm, + toward the lens)", "field (\u00b0)");
    for (std::size_t j = 0; j < a.fieldCurvature.size(); ++j)
        for (bool tangential : {true, false}) {
            PlotSeries s = makeSeries((tangential ? "T " : "S ") + nm(a.wavelengths[j]), SeriesStyle::Line, !tangential);
            for (const FieldCurvatureSample& c : a.fieldCurvature[j]) {
                s.x.push_back(c.found ? (tangential ? c.tangentialShift : c.sagittalShift) : NAN);
                s.y.push_back(c.fieldDegrees);
            }
            p.series.push_back(s);
        }
    return p;
}

Plot distortionPlot(const LensDesignAnalysis& a) {
    Plot p = makePlot("distortion", "Distortion (d line)", "distortion (%)", "field (\u00b0)");
    PlotSeries s = makeSeries("distortion");
    for (const DistortionSample& d : a.distortion) {
        s.x.push_back(d.found ? d.distortionPercent : NAN);
        s.y.push_back(d.fieldDegrees);
    }
    p.series.push_back(s);
    return p;
}

Plot illuminationPlot(const LensDesignAnalysis& a) {
    Plot p = makePlot("relative-illumination", "Relative illumination", "film radius (mm)", "relative illumination");
    p.y.min = 0;
    p.y.max = 1.05;
    PlotSeries s = makeSeries("relative illumination");
    for (const IlluminationSample& i : a.illumination) {
        s.x.push_back(i.filmRadius);
        s.y.push_back(i.relativeIllumination);
    }
    p.series.push_back(s);
    return p;
}

Plot focalShiftPlot(const LensDesignAnalysis& a) {
    Plot p = makePlot("chromatic-focal-shift", "Chromatic focal shift (paraxial)",
                      "focus shift from the d line (mm, + toward the lens)", "wavelength (nm)");
    PlotSeries s = makeSeries("focal shift");
    for (const FocalShiftSample& f : a.focalShiftSpectrum) {
        s.x.push_back(f.shift);
        s.y.push_back(f.wavelength);
    }
    PlotSeries chosen = makeSeries("analysis wavelengths", SeriesStyle::Markers);
    for (const FocalShiftSample& f : a.focalShift) {
        chosen.x.push_back(f.shift);
        chosen.y.push_back(f.wavelength);
    }
    p.series = {s, chosen};
    return p;
}

}  // namespace

std::vector<NamedSvg> designAnalysisPlots(const LensDesignAnalysis& a) {
    std::vector<NamedSvg> plots;
    for (std::size_t i = 0; i < a.fields.size(); ++i) {
        const std::string suffix = "field-" + std::to_string(i + 1);
        plots.push_back({"spot-" + suffix, svgPlot(spotPlot(a.fields[i], "spot-" + suffix))});
        plots.push_back({"mtf-" + suffix, svgPlot(mtfPlot(a, a.fields[i], "mtf-" + suffix))});
        plots.push_back({"fans-" + suffix, svgPlot(fanPlot(a.fields[i], "fans-" + suffix))});
    }
    if (a.largestFieldDegrees) {  // the curves run from the axis to the largest field
        plots.push_back({"field-curvature", svgPlot(fieldCurvaturePlot(a))});
        plots.push_back({"distortion", svgPlot(distortionPlot(a))});
        plots.push_back({"relative-illumination", svgPlot(illuminationPlot(a))});
    }
    plots.push_back({"chromatic-focal-shift", svgPlot(focalShiftPlot(a))});
    return plots;
}

std::string analysisSettingsText(const LensDesignAnalysis& a) {
    const std::string focus = a.lens.focus.infinity ? "infinity" : formatNumber(a.lens.focus.objectZ - a.lens.lens.frontZ(), 5) + " mm";
    return std::string("f/") + formatFNumber(a.lens.fstop) + ", focused at " + focus + "; image plane: " +
           imagePlaneName(a.imagePlane) + " (z " + formatFixed(a.imageZ, 4) + " mm); spot radii about " +
           (a.reference == SpotReference::ChiefRay ? "the chief ray" : "the centroid") + "; primary wavelength " +
           formatFixed(a.primaryWavelength, 2) + " nm; largest field " +
           (a.largestFieldDegrees ? formatFixed(*a.largestFieldDegrees, 2) + "\u00b0 (" + a.largestFieldSource + ")"
                                  : a.largestFieldSource) +
           " (docs/analysis.md defines each number).";
}

}  // namespace lenslab
