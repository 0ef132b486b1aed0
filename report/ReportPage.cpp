#include "ReportPage.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

#include "MarkupText.h"
#include "prescription/NumberText.h"
#include "RenderItems.h"
#include "SlantedEdgeSection.h"
#include "SvgPlot.h"

namespace lenslab {

namespace {

using nlohmann::json;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::string lensAnchor(const std::string& id) { return "lens-" + id; }
std::string sceneAnchor(const std::string& id) { return "scene-" + id; }

// A value from the lens JSON at a dotted path ("F_prime.z"); NaN when absent or null.
double jsonNumber(const json& analysis, const std::string& path) {
    const json* node = &analysis;
    std::istringstream parts(path);
    for (std::string part; std::getline(parts, part, '.');) {
        if (!node->is_object() || !node->contains(part)) return kNaN;
        node = &(*node)[part];
    }
    return node->is_number() ? node->get<double>() : kNaN;
}

struct Row {
    const char* quantity;
    const char* key;  // path in the lens JSON
    int decimals;
    const char* unit;
    const char* meaning;
};

const Row kRows[] = {
    {"Effective focal length", "efl", 4, "mm", "P\u2032 to F\u2032"},
    {"Front focal length", "efl_front", 4, "mm", "F to P"},
    {"Back focal distance", "back_focal_distance", 4, "mm", "rear vertex to F\u2032"},
    {"Front focal distance", "front_focal_distance", 4, "mm", "F to front vertex"},
    {"F (front focal point)", "F.z", 4, "mm", "z"},
    {"F\u2032 (rear focal point)", "F_prime.z", 4, "mm", "z"},
    {"P (front principal plane)", "P.z", 4, "mm", "z"},
    {"P\u2032 (rear principal plane)", "P_prime.z", 4, "mm", "z"},
    {"Aperture stop", "stop.z", 4, "mm", "z"},
    {"Stop diameter", "stop.diameter", 4, "mm", "at this f-number"},
    {"Stop diameter, table", "stop.max_diameter", 4, "mm", "widest opening"},
    {"Entrance pupil", "entrance_pupil.z", 4, "mm", "z"},
    {"Entrance pupil diameter", "entrance_pupil.diameter", 4, "mm", ""},
    {"Exit pupil", "exit_pupil.z", 4, "mm", "z"},
    {"Exit pupil diameter", "exit_pupil.diameter", 4, "mm", ""},
    {"f-number", "fstop", 3, "", "of this table"},
    {"Widest f-number", "fstop_min", 3, "", ""},
    {"Narrowest f-number", "fstop_max", 3, "", ""},
    {"Focus distance", "focus.distance", 1, "mm", "object to front vertex"},
    {"Film plane, exact focus", "focus.image_z", 4, "mm", "z, least RMS spot"},
    {"Film plane, thick lens", "focus.image_z_thick", 4, "mm", "z, lens formula"},
    {"Exact minus thick", "focus.image_z_difference", 4, "mm", ""},
    {"Wavelength", "wavelength_nm", 2, "nm", "of the figures above"},
    {"EFL at F (486.13 nm)", "chromatic.efl_F", 4, "mm", ""},
    {"EFL at C (656.27 nm)", "chromatic.efl_C", 4, "mm", ""},
    {"Longitudinal colour", "chromatic.longitudinal_colour_mm", 4, "mm", "image z at C minus at F"},
    {"Lateral colour", "chromatic.lateral_colour_mm", 4, "mm", "F minus C chief-ray height at the largest field"},
    {"Largest field", "field_of_view.largest_field_deg", 2, "deg", "the analysis's full field; the lateral colour's field"},
};

std::string rate(double perSecond) {
    char b[32];
    if (perSecond >= 1e6) std::snprintf(b, sizeof b, "%.1f M", perSecond / 1e6);
    else std::snprintf(b, sizeof b, "%.0f k", perSecond / 1e3);
    return b;
}

// The picture, linked to itself so that a click shows it at full size.
std::string img(const std::string& src, const std::string& alt, int width, int height) {
    const std::string href = escapeMarkup(src);
    return "<a href=\"" + href + "\"><img src=\"" + href + "\" alt=\"" + escapeMarkup(alt) + "\" width=\"" +
           std::to_string(width) + "\" height=\"" + std::to_string(height) + "\" loading=\"lazy\"></a>";
}

std::string figure(const std::string& body, const std::string& caption, const std::string& cls = "") {
    return "<figure" + (cls.empty() ? "" : " class=\"" + cls + "\"") + ">\n" + body + "\n<figcaption>" + caption +
           "</figcaption>\n</figure>\n";
}

void lensTable(std::ostringstream& out, const LensFacts& f) {
    const json& a = f.analysis;
    out << "<table class=\"lens-data\">\n<caption>First-order data. Units: " << escapeMarkup(a.value("units", "mm"))
        << "; every z in the lens frame: " << escapeMarkup(a.value("convention", "")) << ".</caption>\n"
        << "<thead><tr><th scope=\"col\">Quantity</th><th scope=\"col\">Value</th><th scope=\"col\">Unit</th>"
           "<th scope=\"col\">Meaning</th></tr></thead>\n<tbody>\n";
    for (const Row& r : kRows) {
        const double v = jsonNumber(a, r.key);
        const bool infiniteFocus = std::string(r.key) == "focus.distance" && a["focus"].value("infinity", false);
        out << "<tr><th scope=\"row\">" << r.quantity << "</th>";
        if (infiniteFocus) out << "<td>infinity</td>";
        else if (std::isnan(v)) out << "<td data-key=\"" << r.key << "\">none</td>";
        else out << "<td data-key=\"" << r.key << "\">" << formatFixed(v, r.decimals) << "</td>";
        const bool fieldRow = std::string(r.key) == "field_of_view.largest_field_deg";
        out << "<td>" << r.unit << "</td><td>" << (fieldRow ? escapeMarkup(a["field_of_view"].value("source", "")) : r.meaning)
            << "</td></tr>\n";
    }
    std::string stops;
    for (const auto& s : a["full_stops"]) stops += (stops.empty() ? "f/" : ", f/") + formatNumber(s.get<double>(), 3);
    out << "<tr><th scope=\"row\">Full stops</th><td colspan=\"3\">" << stops << "</td></tr>\n";
    out << "<tr><th scope=\"row\">Image circle radius</th><td>"
        << (f.imageCircleRadius > 0 ? formatFixed(f.imageCircleRadius, 2) : "none")
        << "</td><td>mm</td><td>largest film radius any ray reaches (none: rays reach past 2 EFL + 50 mm, or none the centre)</td></tr>\n";
    out << "</tbody>\n</table>\n";
}

// The small plots in a lens's panel share one size.
Plot lensPanelPlot(const std::string& id, const std::string& title) {
    Plot p;
    p.id = id;
    p.title = title;
    p.width = 420;
    p.height = 280;
    return p;
}

Plot thickErrorPlot(const LensFacts& f) {
    Plot p = lensPanelPlot("thick-" + f.id, "Thick lens against the exact trace");
    p.x.label = "entrance height (mm)";
    p.y.label = "height error at F\u2032 (mm)";
    PlotSeries s{"exact \u2212 thick", {}, {}};
    for (const auto& e : f.thickError) {
        s.x.push_back(e.height);
        s.y.push_back(e.blocked ? kNaN : e.transverseError);
    }
    p.series = {s};
    return p;
}

Plot illuminationPlot(const LensFacts& f) {
    Plot p = lensPanelPlot("illumination-" + f.id, "Relative illumination");
    p.x.label = "film radius (mm)";
    p.y.label = "relative to the centre";
    p.y.min = 0;
    p.y.max = 1;
    PlotSeries light{"illumination (cos\u2074 included)", {}, {}}, area{"passing area (vignetting)", {}, {}};
    area.dash = LineDash::Dashed;
    for (const auto& s : f.illumination) {
        light.x.push_back(s.filmRadius);
        light.y.push_back(s.relativeIllumination);
        area.x.push_back(s.filmRadius);
        area.y.push_back(s.passingArea);
    }
    p.series = {light, area};
    return p;
}

PlotSeries distortionSeries(const LensFacts& f, const std::string& label) {
    PlotSeries s{label, {}, {}};
    for (const auto& d : f.distortion) {
        s.x.push_back(d.fieldDegrees);
        s.y.push_back(d.distortionPercent);
    }
    return s;
}

Plot distortionPlot(const LensFacts& f) {
    Plot p = lensPanelPlot("distortion-" + f.id, "Distortion (object at infinity)");
    p.x.label = "field angle (degrees)";
    p.y.label = "distortion (%)";
    p.series = {distortionSeries(f, "chief ray vs f tan \u03b8")};
    return p;
}

// The chart through a dispersive lens: a wavelength per sample through the glasses' dispersion,
// beside every ray at the lens's own wavelength.
void colourFringes(std::ostringstream& out, const LensFacts& f, const ColourFringes& c) {
    out << "<section class=\"colour\">\n<h4>Lateral colour: the chart at f/" << formatFNumber(c.fstop) << "</h4>\n";
    if (!c.problem.empty()) {
        out << "<p class=\"problem\">" << escapeMarkup(c.problem) << "</p>\n</section>\n";
        return;
    }
    const int w = c.spectral.width, h = c.spectral.height;
    out << "<div class=\"triptych\">\n"
        << figure(img(c.spectral.image, "colour chart through " + f.id + ", spectral", w, h),
                  "Spectral: each sample at its own wavelength through the glasses' dispersion")
        << figure(img(c.rgb.image, "colour chart through " + f.id + ", one wavelength", w, h),
                  "RGB: every ray at the lens's own wavelength, no dispersion")
        << "</div>\n<p class=\"params\">" << w << "\u00d7" << h << " pixels, " << c.spectral.spp
        << " samples per pixel; render " << formatFixed(c.spectral.renderSeconds, 2) << " s spectral, "
        << formatFixed(c.rgb.renderSeconds, 2) << " s RGB.</p>\n</section>\n";
}

bool drawsCurvesAgainstField(const DesignPlots& d) {
    return std::any_of(d.plots.begin(), d.plots.end(), [](const std::string& file) {
        return file.size() >= 15 && file.compare(file.size() - 15, 15, "/distortion.svg") == 0;
    });
}

// The brightest ghosts of the ghost analysis as a table.
void ghostTable(std::ostringstream& out, const nlohmann::json& g) {
    constexpr std::size_t kShown = 8;
    const nlohmann::json& ghosts = g.at("ghosts");
    out << "<table class=\"ghosts\">\n<caption>The " << std::min(kShown, ghosts.size()) << " brightest of " << ghosts.size()
        << " ghosts (" << g.at("reflecting_surfaces").get<int>()
        << " reflecting surfaces), through the coatings at the d line</caption>\n<thead><tr><th scope=\"col\">Surfaces</th>"
           "<th scope=\"col\">R\u2081, R\u2082 (%)</th><th scope=\"col\">Focus from the film (mm)</th>"
           "<th scope=\"col\">Blur \u2300 (mm)</th><th scope=\"col\">Share of the light</th><th scope=\"col\">Intensity</th>"
           "</tr></thead>\n<tbody>\n";
    for (std::size_t i = 0; i < std::min(kShown, ghosts.size()); ++i) {
        const nlohmann::json& x = ghosts[i];
        const nlohmann::json& focus = x.at("focus_from_film_mm");
        out << "<tr" << (x.at("focused").get<bool>() ? " class=\"focused\"" : "") << "><th scope=\"row\">"
            << x.at("surfaces")[0].get<int>() << "\u2013" << x.at("surfaces")[1].get<int>() << "</th><td>"
            << formatFixed(100 * x.at("reflectance")[0].get<double>(), 3) << ", "
            << formatFixed(100 * x.at("reflectance")[1].get<double>(), 3) << "</td><td>"
            << (focus.is_null() ? std::string("\u221e") : formatFixed(focus.get<double>(), 3)) << "</td><td>"
            << formatFixed(x.at("blur_diameter_mm").get<double>(), 3) << "</td><td>" << formatNumber(x.at("energy").get<double>(), 3)
            << "</td><td>" << formatNumber(x.at("relative_intensity").get<double>(), 3) << "</td></tr>\n";
    }
    out << "</tbody>\n</table>\n";
}

// lenslab analyze's plots for the lens, each an SVG file opened full size by a click.
void designSection(std::ostringstream& out, const LensFacts& f, const std::string& fileName, const DesignPlots& d) {
    if (d.plots.empty() && d.problem.empty()) return;  // not asked for
    out << "<section class=\"analysis\" data-lens=\"" << escapeMarkup(f.id) << "\">\n<h4>The lens designer's analysis at f/"
        << formatFNumber(d.fstop) << ", focused at " << escapeMarkup(d.focus) << "</h4>\n";
    if (!d.problem.empty()) {
        out << "<p class=\"problem\">" << escapeMarkup(d.problem) << "</p>\n</section>\n";
        return;
    }
    out << d.settingsHtml << "<div class=\"analysis-tables\">\n" << d.tablesHtml << "</div>\n<div class=\"plots design-plots\">\n";
    for (std::size_t i = 0; i < d.plots.size(); ++i) {
        const std::string href = escapeMarkup(d.plots[i]), caption = i < d.captions.size() ? d.captions[i] : "";
        out << figure("<a href=\"" + href + "\"><img src=\"" + href + "\" alt=\"" + escapeMarkup(f.id + ": " + caption) +
                          "\" loading=\"lazy\"></a>",
                      escapeMarkup(caption));
    }
    out << "</div>\n";
    if (d.ghosts.contains("ghosts")) ghostTable(out, d.ghosts);
    out << "<p class=\"download\"><a href=\"" << escapeMarkup(d.jsonFile)
        << "\">The analysis as JSON</a> (the output of <code>lenslab analyze " << escapeMarkup(fileName)
        << " --json</code> with the settings above; the ghosts: <code>--ghosts --json</code>).</p>\n</section>\n";
}

// What a lens file holds, by its content: an upload is stored under an id whatever it was.
std::string lensFileKind(const LensFacts& f) {
    const std::string format = f.analysis.value("format", std::string());
    return format == "zmx" ? "a Zemax .zmx prescription" : format == "seq" ? "a Code V .seq prescription" : "a lens table (.dat)";
}

void lensArticle(std::ostringstream& out, const LensEntry& lens) {
    const LensFacts& f = lens.facts;
    out << "<article class=\"lens\" id=\"" << escapeMarkup(lensAnchor(f.id)) << "\">\n<h3>" << escapeMarkup(lens.name) << "</h3>\n";
    if (!f.description.empty()) out << "<p class=\"design\">" << escapeMarkup(f.description) << "</p>\n";
    if (!f.error.empty()) {
        out << "<p class=\"problem\">This lens could not be analysed: " << escapeMarkup(f.error) << "</p>\n</article>\n";
        return;
    }
    out << "<div class=\"lens-layout\">\n";
    lensTable(out, f);
    out << "<div class=\"diagrams\">\n";
    for (const DiagramImage& d : lens.diagrams)
        out << figure(img(d.image, f.id + " cross-section, " + d.mode + " trace", d.width, d.height),
                      d.mode == "exact" ? "Exact trace through every surface"
                      : d.mode == "thick" ? "Thick-lens approximation (principal planes and pupils)"
                                          : "Both overlaid: exact and thick-lens rays");
    if (!lens.problem.empty()) out << "<p class=\"problem\">" << escapeMarkup(lens.problem) << "</p>\n";
    out << "</div>\n</div>\n<div class=\"plots\">\n";
    out << figure(svgPlot(thickErrorPlot(f)), "Rays parallel to the axis across the entrance pupil, where each crosses the F\u2032 plane.");
    // The designer's analysis below draws relative illumination and distortion against field: the
    // panel draws its own only where that analysis draws none (no largest field, or not asked for).
    if (!drawsCurvesAgainstField(lens.design)) {
        out << figure(svgPlot(illuminationPlot(f)),
                      "Irradiance from a uniform scene on the film at the exact focus, by exact tracing; 1 at the centre.");
        out << figure(svgPlot(distortionPlot(f)), "Chief ray height on the F\u2032 plane against f tan \u03b8; negative is barrel.");
    }
    out << "</div>\n";
    designSection(out, f, lens.fileName, lens.design);
    if (lens.colourFringes) colourFringes(out, f, *lens.colourFringes);
    out << "<p class=\"download\"><a href=\"" << escapeMarkup(lens.jsonFile) << "\">The table as JSON</a> (the output of <code>lenslab lens "
        << escapeMarkup(lens.fileName) << " --json</code> with the settings above; " << lensFileKind(f)
        << ").</p>\n</article>\n";
}

void statsTable(std::ostringstream& out, const RenderPair& pair) {
    out << "<table class=\"render-stats\">\n<thead><tr><th scope=\"col\">Camera</th><th scope=\"col\">Setup (s)</th>"
           "<th scope=\"col\">Render (s)</th><th scope=\"col\">Camera rays</th><th scope=\"col\">Blocked by the lens</th>"
           "<th scope=\"col\">Rays/s</th></tr></thead>\n<tbody>\n";
    for (const RenderRecord* r : {&pair.accurate, &pair.approximate}) {
        const double blocked = r->cameraRays ? 100.0 * r->blockedCameraRays / r->cameraRays : 0;
        out << "<tr><th scope=\"row\">" << r->mode << "</th><td>" << formatFixed(r->setupSeconds, 2) << "</td><td>"
            << formatFixed(r->renderSeconds, 2) << "</td><td>" << r->cameraRays << "</td><td>" << formatFixed(blocked, 1)
            << " %</td><td>" << rate(r->renderSeconds > 0 ? r->raysTraced / r->renderSeconds : 0) << "</td></tr>\n";
    }
    out << "</tbody>\n</table>\n";
}

void sceneArticle(std::ostringstream& out, const ReportScene& s) {
    out << "<article class=\"scene\" id=\"" << escapeMarkup(sceneAnchor(s.scene.id)) << "\">\n<h3>Scene "
        << escapeMarkup(s.scene.id) << "</h3>\n";
    if (!s.scene.description.empty())
        out << "<p class=\"design\">" << escapeMarkup(s.scene.description) << (s.scene.description.back() == '.' ? "" : ".")
            << " Below, its own lens is replaced by each lens of common scale.</p>\n";
    if (!s.scene.realisticCamera) {
        out << "<p>This scene has a pinhole (perspective) camera: the lenses do not apply to it.</p>\n</article>\n";
        return;
    }
    for (const RenderPair& p : s.pairs) {
        out << "<section class=\"comparison\">\n<h4>" << escapeMarkup(p.lensId) << " at f/" << formatNumber(p.accurate.fstop, 3)
            << "</h4>\n";
        if (!p.problem.empty()) {
            out << "<p class=\"problem\">" << escapeMarkup(p.problem) << "</p>\n</section>\n";
            continue;
        }
        const int w = p.accurate.width, h = p.accurate.height;
        out << "<div class=\"triptych\">\n"
            << figure(img(p.accurate.image, s.scene.id + " through " + p.lensId + ", exact lens trace", w, h),
                      "Exact: every ray traced through the lens")
            << figure(img(p.approximate.image, s.scene.id + " through " + p.lensId + ", thick-lens camera", w, h),
                      "Thick: the thick-lens model")
            << figure(img(p.differenceImage, "difference between the two renders", w, h),
                      "|difference| \u00d7 " + formatNumber(p.differenceGain, 3) + ", RMS " + formatFixed(p.rmsDifference, 2) +
                          " of 255")
            << "</div>\n";
        statsTable(out, p);
        out << "<p class=\"params\">" << p.accurate.width << "\u00d7" << p.accurate.height << " pixels, " << p.accurate.spp
            << " samples per pixel, f/" << formatNumber(p.accurate.fstop, 3) << ", focus and film as the scene sets them; "
            << "PNG exposure \u00d7" << formatNumber(p.accurate.exposure, 3) << " (4N\u00b2/\u03c0, the scene's brightness).</p>\n";
        out << "</section>\n";
    }
    out << "</article>\n";
}

void comparisonPlots(std::ostringstream& out, const ReportContent& c) {
    Plot light;
    light.id = "illumination-all";
    light.title = "Relative illumination of every lens";
    light.x.label = "film radius (mm)";
    light.y.label = "relative to the centre";
    light.y.min = 0;
    light.y.max = 1;
    light.width = 640;
    light.height = 360;
    Plot distortion = light;
    distortion.id = "distortion-all";
    distortion.title = "Distortion of every lens";
    distortion.x.label = "field angle (degrees)";
    distortion.y = PlotAxis{};
    distortion.y.label = "distortion (%)";
    for (const LensEntry& l : c.lenses) {
        if (!l.facts.error.empty()) continue;
        PlotSeries s{l.name, {}, {}};
        for (const auto& i : l.facts.illumination) {
            s.x.push_back(i.filmRadius);
            s.y.push_back(i.relativeIllumination);
        }
        light.series.push_back(s);
        distortion.series.push_back(distortionSeries(l.facts, l.name));
    }
    out << "<div class=\"plots wide\">\n"
        << figure(svgPlot(light), "Each curve ends at the lens's image circle; the lenses at the f-number of their tables.")
        << figure(svgPlot(distortion), "Chief rays, object at infinity, up to the image circle. Distortion does not "
                                       "change with scale: a course original and its scaled copy draw one curve.");
    if (!c.speed.points.empty()) {
        Plot speed;
        speed.id = "speed";
        speed.title = "Speed against accuracy";
        speed.x.label = "render time, setup included (s)";
        speed.y.label = "RMS error (8-bit levels)";
        speed.x.logarithmic = speed.y.logarithmic = true;
        speed.width = 640;
        speed.height = 360;
        for (const char* mode : {"exact", "thick"}) {
            PlotSeries s{std::string(mode) == "exact" ? "exact (every ray through the lens)" : "thick (thick-lens model)", {}, {}};
            s.style = SeriesStyle::LineAndMarkers;
            for (const SpeedPoint& p : c.speed.points)
                if (p.mode == mode) {
                    s.x.push_back(p.seconds);
                    s.y.push_back(p.rmsError);
                }
            speed.series.push_back(s);
        }
        out << figure(svgPlot(speed), "Scene " + escapeMarkup(c.speed.sceneId) + " through " + escapeMarkup(c.speed.lensId) +
                                          ": error against the accurate render at " + std::to_string(c.speed.referenceSpp) +
                                          " samples per pixel, as the sample count doubles from 1. The thick lens is "
                                          "cheaper per sample but levels off at its own bias.");
    }
    out << "</div>\n";
}

// The sensor ladder (docs/sensor.md): crops at rising ISO, each captioned with its exposure and noise.
void sensorLadderSection(std::ostringstream& out, const SensorLadder& l) {
    out << "<section id=\"sensor-ladder\">\n<h2>A real sensor: ISO " << formatNumber(kSensorLadderIsos[0]) << " to "
        << formatNumber(kSensorLadderIsos[std::size(kSensorLadderIsos) - 1]) << "</h2>\n<p>Scene " << escapeMarkup(l.sceneId)
        << " through " << escapeMarkup(l.lensId) << " behind a full-frame sensor of 4.35 \u00b5m pixels (Nikon D850's "
           "pitch; shot noise, read noise, dark current, fixed patterns, a 14-bit ADC), a crop at 100%, the exposure "
           "metered so every ISO shows the same brightness: each step collects a quarter of the light. Noise: the rms "
           "of each pixel's green minus its 5\u00d75 neighbourhood's mean, over the mean (8-bit sRGB).</p>\n";
    if (!l.problem.empty()) out << "<p class=\"problem\">" << escapeMarkup(l.problem) << "</p>\n";
    out << "<div class=\"plots\">\n";
    for (const SensorRung& r : l.rungs)
        out << figure(img(r.render.image, l.lensId + " behind a sensor at ISO " + formatNumber(r.iso), r.render.width, r.render.height),
                      "ISO " + formatNumber(r.iso) + ": noise " + formatFixed(r.noise, 3) + ", render " +
                          formatFixed(r.render.renderSeconds, 2) + " s");
    out << "</div>\n</section>\n";
}

}  // namespace

std::string reportHtml(const ReportContent& c) {
    std::ostringstream out;
    out << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
           "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
           "<title>lenslab report</title>\n<link rel=\"icon\" href=\"data:,\">\n"
           "<link rel=\"stylesheet\" href=\"style.css\">\n</head>\n<body>\n<header>\n<h1>lenslab report</h1>\n"
        << "<p class=\"lede\">Real camera lenses from their lens tables: first-order data, cross-sections, illumination "
           "and distortion measured by exact tracing, and renders through the glass against the thick-lens "
           "approximation (after Kolb, Mitchell &amp; Hanrahan, SIGGRAPH 1995). Generated "
        << escapeMarkup(c.generatedAt) << " by lenslab " << escapeMarkup(c.version) << ".</p>\n<ul class=\"parameters\">\n";
    for (const std::string& p : c.parameters) out << "<li>" << escapeMarkup(p) << "</li>\n";
    out << "</ul>\n<nav aria-label=\"Contents\">\n<ol>\n<li><a href=\"#conventions\">Conventions</a></li>\n"
           "<li><a href=\"#lenses\">Lenses</a>:";
    for (const LensEntry& l : c.lenses)
        out << " <a href=\"#" << escapeMarkup(lensAnchor(l.facts.id)) << "\">" << escapeMarkup(l.name) << "</a>";
    out << "</li>\n<li><a href=\"#renders\">Renders</a>:";
    for (const ReportScene& s : c.scenes)
        out << " <a href=\"#" << escapeMarkup(sceneAnchor(s.scene.id)) << "\">" << escapeMarkup(s.scene.id) << "</a>";
    out << "</li>\n<li><a href=\"#plots\">Comparison plots</a></li>\n";
    if (!c.slantedEdges.plots.empty()) out << "<li><a href=\"#render-against-analysis\">The render against the analysis</a></li>\n";
    if (!c.sensorLadder.rungs.empty()) out << "<li><a href=\"#sensor-ladder\">A real sensor</a></li>\n";
    out << "<li><a href=\"#algorithms\">How it works</a></li>\n";
    if (!c.problems.empty()) out << "<li><a href=\"#problems\">Problems</a></li>\n";
    out << "</ol>\n</nav>\n</header>\n<main>\n";

    out << "<section id=\"conventions\">\n<h2>Conventions</h2>\n<p>Lengths are in millimetres. Every z is measured in "
           "the lens frame: the origin at the front (scene-side) vertex, +z toward the scene, the elements and the film "
           "at negative z. F, F\u2032, P and P\u2032 are the front and rear focal points and principal planes. The "
           "f-number is that of the image-side cone for an object at infinity, 1/(2 sin \u03b8). Focus distances run from "
           "the object to the front vertex.</p>\n</section>\n";

    out << "<section id=\"lenses\">\n<h2>Lenses</h2>\n";
    for (const LensEntry& l : c.lenses) lensArticle(out, l);
    out << "</section>\n<section id=\"renders\">\n<h2>Renders</h2>\n<p>Each scene with a realistic camera, through each "
           "lens of common scale, rendered with the exact lens trace (accurate) and with the thick-lens camera "
           "(approximate). The difference is that of the 8-bit pictures, amplified; white means identical.</p>\n";
    if (c.scenes.empty()) out << "<p class=\"problem\">No scenes were found.</p>\n";
    for (const ReportScene& s : c.scenes) sceneArticle(out, s);
    out << "</section>\n<section id=\"plots\">\n<h2>Comparison plots</h2>\n";
    comparisonPlots(out, c);
    out << "</section>\n" << slantedEdgeSectionHtml(c.slantedEdges);
    if (!c.sensorLadder.rungs.empty() || !c.sensorLadder.problem.empty()) sensorLadderSection(out, c.sensorLadder);
    out << algorithmsSectionHtml();
    if (!c.problems.empty()) {
        out << "<section id=\"problems\">\n<h2>Problems</h2>\n<ul>\n";
        for (const std::string& p : c.problems) out << "<li>" << escapeMarkup(p) << "</li>\n";
        out << "</ul>\n</section>\n";
    }
    out << "</main>\n<footer>\n<p>lenslab " << escapeMarkup(c.version)
        << ". The source: optics/ (lens physics), renderer/ (diagrams, ray tracer), report/ (this page).</p>\n"
           "</footer>\n</body>\n</html>\n";
    return out.str();
}

}  // namespace lenslab
