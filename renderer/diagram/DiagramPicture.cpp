#include "DiagramPicture.h"

#include "prescription/NumberText.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <optional>

#include "DiagramStyle.h"
#include "LensLayout.h"

namespace lenslab {

namespace {

using namespace diagram_style;

std::string millimetres(double value) { return formatFixed(value, std::abs(value) >= 100 ? 0 : 1) + " mm"; }

const char* modeName(DiagramMode mode) {
    switch (mode) {
        case DiagramMode::Exact: return "exact";
        case DiagramMode::Thick: return "thick";
        case DiagramMode::Overlay: return "overlay";
    }
    return "";
}

// What the picture shows; a folded (mirror) lens has no thick-lens rays, whatever the mode asked.
const char* modeCaption(DiagramMode mode, bool colourFans, bool folded) {
    if (folded && mode == DiagramMode::Thick) return "no thick-lens rays (mirrors)";
    if (folded) mode = DiagramMode::Exact;
    switch (mode) {
        case DiagramMode::Exact: return colourFans ? "exact rays at F, d, C" : "exact rays";
        case DiagramMode::Thick: return "thick-lens rays";
        case DiagramMode::Overlay: return colourFans ? "exact rays at F, d, C and thick-lens rays" : "exact and thick-lens rays";
    }
    return "";
}

// Labels in two rows above or below the lens. Each goes in the first row with room near its
// target, sliding sideways past its neighbours when needed; a thin leader joins it to the target.
struct LabelRows {
    double firstBaseline = 0;
    double rowStep = 0;  // negative: rows stack upward
    std::vector<std::vector<std::pair<double, double>>> taken{2};

    // Returns the label's centre x and baseline.
    Point2 place(double x, double halfWidth) {
        for (std::size_t row = 0; row < taken.size(); ++row) {
            auto& spans = taken[row];
            auto fits = [&](double c) {
                return std::none_of(spans.begin(), spans.end(), [&](const auto& span) {
                    return c + halfWidth > span.first && c - halfWidth < span.second;
                });
            };
            std::vector<double> candidates{x};
            for (const auto& span : spans) {
                candidates.push_back(span.second + halfWidth);
                candidates.push_back(span.first - halfWidth);
            }
            std::sort(candidates.begin(), candidates.end(),
                      [&](double a, double b) { return std::abs(a - x) < std::abs(b - x); });
            for (double c : candidates) {
                if (std::abs(c - x) > 3 * halfWidth || !fits(c)) continue;
                spans.push_back({c - halfWidth, c + halfWidth});
                return {c, firstBaseline + rowStep * static_cast<double>(row)};
            }
        }
        return {x, firstBaseline + rowStep * static_cast<double>(taken.size() - 1)};
    }
};

struct Composer {
    const LensAnalysis& a;
    const DiagramOptions& options;
    DiagramPicture& pic;
    int em = 14, small = 12;  // text sizes, pixels
    double lw = 1;            // line width unit, pixels
    LabelRows above{}, below{};

    Point2 at(ZY p) const { return pic.view.toPicture(p); }

    void label(Point2 p, const std::string& text, int size, Rgba colour, TextAnchor anchor = TextAnchor::Centre) {
        pic.labels.push_back({p, text, size, colour, anchor});
    }

    // A name in the rows above (up) or below the content, led to `target`.
    void rowLabel(bool up, Point2 target, const std::string& text, Rgba colour) {
        LabelRows& rows = up ? above : below;
        const Point2 spot = rows.place(target.x, 0.5 * textWidth(text, small) + 0.4 * small);
        const double labelEdge = up ? spot.y + 0.3 * small : spot.y - small;
        addLine(pic.shapes, {spot.x, labelEdge}, target, 0.8 * lw, kLeader);
        label(spot, text, small, colour);
    }

    void glass(const LensOutline& outline) {
        for (const GlassElement& g : outline.glass)
            for (std::size_t i = 1; i < g.front.size(); ++i)
                addQuad(pic.shapes, at(g.front[i - 1]), at(g.rear[i - 1]), at(g.rear[i]), at(g.front[i]), kGlass);
    }

    void lensLines(const LensOutline& outline) {
        std::vector<Point2> points;
        for (const auto& line : outline.lines) {
            points.clear();
            for (const ZY& p : line) points.push_back(at(p));
            addPolyline(pic.shapes, points, 1.5 * lw, kLensLine);
        }
    }

    // A point at height y and z of a space of the lens (object space, image space: LensLayout.h).
    Point2 at(const RigidMotion& space, double y, double z) const { return at(LensLayout::place(space, {0, y, z})); }

    void stop(const StopBlades& s) {
        for (const Bar& blade : {s.upper, s.lower}) addLine(pic.shapes, at(blade.from), at(blade.to), 3.5 * lw, kStop);
        rowLabel(true, at(s.upper.to), "stop f/" + formatFNumber(a.fstop), kStop);
    }

    // Across the picture; a folded or decentred lens's axis is the path of its axis ray, from the
    // scene to the film.
    void axis(const std::vector<ZY>& folded) {
        const double y = pic.view.yAtAxis;
        if (folded.empty()) {
            addDashedPolyline(pic.shapes, {{pic.content.left, y}, {pic.content.right, y}}, lw, 9 * lw, 4 * lw, kAxis);
        } else {
            std::vector<Point2> points{{pic.content.left, y}};
            for (const ZY& p : folded) points.push_back(at(p));
            for (const auto& piece : clipPolyline(points, pic.content)) addDashedPolyline(pic.shapes, piece, lw, 9 * lw, 4 * lw, kAxis);
        }
        label({pic.content.left + 0.2 * small, y - 0.35 * small}, "optical axis", small, kNote, TextAnchor::Left);
    }

    void film(const RigidMotion& space, double filmZ, double halfHeight) {
        addLine(pic.shapes, at(space, halfHeight, filmZ), at(space, -halfHeight, filmZ), 2.5 * lw, kFilm);
        rowLabel(false, at(space, -halfHeight, filmZ), "film", kFilm);
    }

    void principalPlane(const RigidMotion& space, double z, double halfHeight, const std::string& name) {
        addDashedPolyline(pic.shapes, {at(space, halfHeight, z), at(space, -halfHeight, z)}, lw, 5 * lw, 4 * lw, faded(kCardinal));
        rowLabel(false, at(space, -halfHeight, z), name, kCardinal);
    }

    void focalPoint(const RigidMotion& space, double z, const std::string& name) {
        const Point2 p = at(space, 0, z);
        addDisc(pic.shapes, p, 3.5 * lw, kCardinal);
        label({p.x, p.y + 1.3 * small}, name, small, kCardinal);
    }

    void pupil(const RigidMotion& space, double z, double diameter, const std::string& name) {
        const double r = diameter / 2, tick = 5 * lw;
        const Point2 top = at(space, r, z), bottom = at(space, -r, z);
        addDashedPolyline(pic.shapes, {top, bottom}, lw, 2 * lw, 3 * lw, kPupil);
        for (const Point2& end : {top, bottom}) addLine(pic.shapes, {end.x - tick, end.y}, {end.x + tick, end.y}, 2.5 * lw, kPupil);
        rowLabel(true, top, name, kPupil);
    }

    // A marker outside the picture (at `where`, z of its space): an arrow at the edge on the axis,
    // stacked per edge.
    void offPicture(ZY where, double z, const std::string& name, int stackIndex) {
        const bool leftEdge = pic.view.toPicture(where).x < pic.content.left;
        const double x = leftEdge ? pic.content.left : pic.content.right;
        const double y = pic.view.yAtAxis + (1.8 + 1.4 * stackIndex) * small;
        addArrowHead(pic.shapes, {x, y}, leftEdge ? -1 : 1, 0, 9 * lw, kCardinal);
        const double inset = 10 * lw + 0.3 * small;
        label({leftEdge ? x + inset : x - inset, y + 0.35 * small}, name + " at z = " + millimetres(z) + " (off picture)",
              small, kCardinal, leftEdge ? TextAnchor::Left : TextAnchor::Right);
    }

    static Rgba rayColour(const FanRay& ray) {
        if (ray.model == RayModel::Thick) return kThickRay;
        if (ray.wavelength == kWavelengthF) return kLineF;
        if (ray.wavelength == kWavelengthD) return kLineD;
        if (ray.wavelength == kWavelengthC) return kLineC;
        return kExactRay;
    }

    void mirrors(const LensOutline& outline) {
        std::vector<Point2> points;
        for (const auto& line : outline.mirrors) {
            points.clear();
            for (const ZY& p : line) points.push_back(at(p));
            addPolyline(pic.shapes, points, 4 * lw, kMirror);
        }
        for (const Obscuration& o : outline.obscurations) {
            addLine(pic.shapes, at(o.from), at(o.to), 5 * lw, kStop);
            rowLabel(false, at(o.to), "obscuration", kStop);
        }
    }

    // Where the F, d and C fans coincide the one drawn last would hide the others, so each line is
    // drawn narrower than the one before it (C widest, then d, F on top): every ray stays at its true
    // place, and where the three share a path all three colours show, C's at the edges, F's in the middle.
    double rayWidth(const FanRay& ray) const {
        if (ray.wavelength == kWavelengthC) return 5.0 * lw;
        if (ray.wavelength == kWavelengthD) return 3.2 * lw;
        if (ray.wavelength == kWavelengthF) return 1.4 * lw;
        return 1.3 * lw;
    }

    // An arriving ray is a solid line to the film; a blocked one is dashed and faded, from the object
    // side to the cross where it stops.
    void rays(const std::vector<FanRay>& fans) {
        for (const FanRay& ray : fans) {
            const Rgba colour = rayColour(ray);
            std::vector<Point2> points;
            for (const ZY& p : ray.points) points.push_back(at(p));
            for (const auto& piece : clipPolyline(points, pic.content)) {
                if (ray.blocked) addDashedPolyline(pic.shapes, piece, std::min(rayWidth(ray), 1.3 * lw), 6 * lw, 4 * lw, faded(colour));
                else addPolyline(pic.shapes, piece, rayWidth(ray), colour);
            }
            if (ray.blocked) addCross(pic.shapes, points.back(), 3.5 * lw, 1.6 * lw, kBlockMark);
        }
    }

    // The first of `variants` (longest first) that fits in `room` pixels at this size, else the last.
    static const std::string& firstFitting(const std::vector<std::string>& variants, int size, double room) {
        for (const std::string& v : variants)
            if (textWidth(v, size) <= room) return v;
        return variants.back();
    }

    // Two lines at the top. On narrow pictures they shorten; the orientation always shows, and so does
    // a folded or decentred lens's being drawn as laid out in space.
    void caption(const std::string& lensName, double filmZ, bool laidOut) {
        const FocusResult& f = a.focus;
        const std::string focus = f.infinity ? "\u221E" : millimetres(f.objectZ);
        const std::string lens = lensName + "   EFL " + formatFixed(a.firstOrder.efl, 2) + " mm   f/" + formatFNumber(a.fstop);
        const double room = pic.width - pic.content.left;
        label({pic.content.left, 1.35 * em},
              firstFitting({lens + "   focus " + focus + "   " + modeCaption(options.mode, options.colourFans, a.lens.hasMirrors()),
                            lens + "   focus " + focus + "   " + modeName(options.mode), lens},
                           em, room),
              em, kText, TextAnchor::Left);
        const bool offAxis = pic.fieldDegrees > 0;
        const std::string field = offAxis ? formatFixed(pic.fieldDegrees, 2) + "\u00B0" : "";
        const std::string full = laidOut ? "laid out in space (folds, tilts and decentres placed), the scene on the left"
                                         : "front (scene side) on the left, film on the right";
        const std::string brief = laidOut ? "laid out in space" : "front on the left";
        const std::string filmAt = millimetres(filmZ) + (laidOut ? " (image space)" : "");
        const std::string note = firstFitting(
            {full + ";  film at z = " + filmAt +
                 (offAxis ? ";  field " + field + ", imaged " + millimetres(pic.fieldHeight) + " below the axis" : ""),
             brief + ";  film z = " + filmAt + (offAxis ? ";  field " + field : ""), brief},
            small, room);
        label({pic.content.left, 1.35 * em + 1.3 * small}, note, small, kNote, TextAnchor::Left);
    }

    // Ray colours, the blocked-ray mark and a scale bar along the bottom edge; the legend's words
    // shorten when the full ones would run into the scale bar.
    void legend() {
        const double baseline = pic.height - 0.55 * small, mid = baseline - 0.35 * small;
        const double scaleLeft = scaleBar(baseline, mid);
        const bool exact = options.mode != DiagramMode::Thick, thick = options.mode != DiagramMode::Exact;
        auto width = [&](const std::array<const char*, 3>& words) {
            double w = 2.6 * small + textWidth(words[2], small);
            for (int i = 0; i < 2; ++i)
                if (i == 0 ? exact : thick) w += 3.4 * small + textWidth(words[i], small);
            return w;
        };
        // A folded lens's thick-lens model has no straight path to draw: the legend says why it is missing.
        const bool thickOmitted = a.lens.hasMirrors();
        const std::array<const char*, 3> full = {
            "exact rays", thickOmitted ? "no thick-lens rays: a mirror lens folds the light" : "thick-lens rays",
            "blocked ray (dashed, to where it stops)"};
        const std::array<const char*, 3> brief = {"exact", thickOmitted ? "no thick-lens rays (mirrors)" : "thick lens",
                                                  "blocked"};
        const auto& words = width(full) <= scaleLeft - pic.content.left - small ? full : brief;
        double x = pic.content.left;
        auto entry = [&](Rgba colour, const std::string& text) {
            addLine(pic.shapes, {x, mid}, {x + 1.8 * small, mid}, 2 * lw, colour);
            label({x + 2.2 * small, baseline}, text, small, kText, TextAnchor::Left);
            x += 2.2 * small + textWidth(text, small) + 1.2 * small;
        };
        auto note = [&](const std::string& text) {
            label({x, baseline}, text, small, kNote, TextAnchor::Left);
            x += textWidth(text, small) + 1.2 * small;
        };
        if (exact && options.colourFans) {
            for (const auto& [colour, name] : {std::pair{kLineF, "F 486 nm"}, {kLineD, "d 588 nm"}, {kLineC, "C 656 nm"}})
                entry(colour, name);
        } else if (exact) {
            entry(kExactRay, words[0]);
        }
        if (thick && thickOmitted) note(words[1]);
        else if (thick) entry(kThickRay, words[1]);
        addDashedPolyline(pic.shapes, {{x, mid}, {x + 1.8 * small, mid}}, 1.3 * lw, 6 * lw, 4 * lw, faded(kExactRay));
        addCross(pic.shapes, {x + 1.8 * small, mid}, 3.5 * lw, 1.6 * lw, kBlockMark);
        label({x + 2.6 * small, baseline}, words[2], small, kText, TextAnchor::Left);
    }

    // A 1-2-5 length near 120 pixels at the right end of the bottom edge; returns where its label starts.
    double scaleBar(double baseline, double mid) {
        const double target = 120.0 / pic.view.scale;
        const double decade = std::pow(10.0, std::floor(std::log10(target)));
        double length = decade;
        for (double m : {2.0, 5.0, 10.0})
            if (m * decade <= target) length = m * decade;
        const double right = pic.content.right, left = right - length * pic.view.scale;
        addLine(pic.shapes, {left, mid}, {right, mid}, 2 * lw, kText);
        for (double end : {left, right}) addLine(pic.shapes, {end, mid - 4 * lw}, {end, mid + 4 * lw}, 1.5 * lw, kText);
        const std::string text = formatFixed(length, length >= 1 ? 0 : 1) + " mm";
        label({left - 0.5 * small, baseline}, text, small, kText, TextAnchor::Right);
        return left - 0.5 * small - textWidth(text, small);
    }
};

struct Marker {
    enum Kind { FocalPoint, PrincipalPlane, Pupil } kind;
    double z;
    std::string name;
    double diameter = 0;     // pupils
    bool imageSide = false;  // in image space (F', P', the exit pupil), else in object space
};

// The view of a lens whose surfaces never move, along its axis: film to a little in front of the
// lens, or to the focused object when it is near; cardinal points and pupils join when they are not
// far off (the others get edge arrows).
ViewTransform axialView(const LensAnalysis& a, const LensOutline& outline, const std::vector<Marker>& markers,
                        double filmHalf, const PictureBox& content) {
    const double filmZ = a.focus.imageZExact, frontZ = a.lens.frontZ();
    const double span = frontZ - filmZ;
    const bool objectInView = !a.focus.infinity && a.focus.objectZ - frontZ <= 2 * span;
    double zMax = objectInView ? a.focus.objectZ + 0.04 * span : frontZ + 0.45 * span;
    double zMin = std::min(filmZ, a.firstOrder.zFPrime) - 0.04 * span;
    for (const Marker& m : markers) {
        if (m.z > frontZ + 1.2 * span || m.z < filmZ - 0.5 * span) continue;
        zMax = std::max(zMax, m.z + 0.04 * span);
        zMin = std::min(zMin, m.z - 0.04 * span);
    }
    const double yHalf = 1.08 * std::max({outline.maxRadius, filmHalf, a.pupils.entrance.diameter / 2,
                                          a.pupils.exit.diameter / 2});
    return fitView(zMin, zMax, yHalf, content);
}

// The drawn points of a marker (a pupil's or a plane's ends, a focal point), where its space lies.
std::vector<ZY> markerPoints(const Marker& m, const LensLayout& layout, double planeHalf) {
    const RigidMotion space = m.imageSide ? layout.imageSpace : RigidMotion{};
    const double half = m.kind == Marker::Pupil ? m.diameter / 2 : m.kind == Marker::PrincipalPlane ? planeHalf : 0;
    return {LensLayout::place(space, {0, half, m.z}), LensLayout::place(space, {0, -half, m.z})};
}

// A folded or decentred lens is drawn as laid out: the lens, the film and the rays, each where it
// lies; a marker joins the view when it lies within half the lens's size of them.
struct LaidOutView {
    ZYBounds lens;  // the outline and the film
    ViewTransform fit(const std::vector<ZY>& drawn, const std::vector<Marker>& markers, const LensLayout& layout,
                      double planeHalf, const PictureBox& content) const {
        std::vector<ZY> all = drawn;
        const ZYBounds near = lens.grownBy(0.5 * lens.span());
        for (const Marker& m : markers) {
            const std::vector<ZY> points = markerPoints(m, layout, planeHalf);
            if (std::all_of(points.begin(), points.end(), [&](ZY p) { return near.holds(p); }))
                all.insert(all.end(), points.begin(), points.end());
        }
        const ZYBounds b = ZYBounds::around(all);
        const ZYBounds shown = b.grownBy(0.04 * b.span());
        return fitView(shown.zMin, shown.zMax, shown.yMin, shown.yMax, content);
    }
};

}  // namespace

DiagramPicture composeDiagram(const LensAnalysis& a, const std::string& lensName, const DiagramOptions& options) {
    DiagramPicture pic;
    pic.width = options.width;
    pic.height = options.height;
    Composer c{a, options, pic};
    const double unit = std::min(pic.width, 2 * pic.height) / 1200.0;
    c.em = std::clamp(static_cast<int>(std::lround(17 * unit)), 11, 48);
    c.small = std::clamp(static_cast<int>(std::lround(14 * unit)), 10, 40);
    c.lw = std::clamp(unit, 0.8, 4.0);

    const LensLayout layout = layOutLens(a.lens);
    LensOutline outline = buildLensOutline(a.lens, layout, MirrorBores{});  // holes in mirrors follow once the rays are known
    const double filmZ = a.focus.imageZExact;
    pic.fieldDegrees = options.fieldHeight ? fieldForFilmHeight(a, filmZ, *options.fieldHeight) : automaticFanField(a);
    pic.fieldHeight = chiefFilmHeight(a, filmZ, pic.fieldDegrees);
    const double filmHalf = std::max(1.25 * pic.fieldHeight, 0.3 * outline.maxRadius);
    const double planeHalf = 1.05 * outline.maxRadius;
    const std::vector<Marker> markers{
        {Marker::FocalPoint, a.firstOrder.zF, "F"},
        {Marker::FocalPoint, a.firstOrder.zFPrime, "F\u2032", 0, true},
        {Marker::PrincipalPlane, a.firstOrder.zP, "P"},
        {Marker::PrincipalPlane, a.firstOrder.zPPrime, "P\u2032", 0, true},
        {Marker::Pupil, a.pupils.entrance.z, "entrance pupil", a.pupils.entrance.diameter},
        {Marker::Pupil, a.pupils.exit.z, "exit pupil", a.pupils.exit.diameter, true}};
    c.above = {1.35 * c.em + 1.3 * c.small + 2.9 * c.small, -1.3 * c.small};
    pic.content = {1.0 * c.em, c.above.firstBaseline + 0.5 * c.small, pic.width - 1.0 * c.em,
                   pic.height - 1.6 * c.small - 2.9 * c.small};
    c.below = {pic.content.bottom + 1.2 * c.small, 1.3 * c.small};

    FanSetup setup;
    setup.filmZ = filmZ;
    setup.fieldDegrees = pic.fieldDegrees;
    setup.rays = options.rays;
    std::optional<LaidOutView> laidOut;
    if (layout.moved) {
        std::vector<ZY> lens = outline.points();
        for (double y : {filmHalf, -filmHalf}) lens.push_back(layout.inImageSpace(y, filmZ));
        laidOut = LaidOutView{ZYBounds::around(lens)};
        // The rays start in front of everything drawn, or at the object when it is near.
        const double span = laidOut->lens.span(), front = laidOut->lens.zMax;
        const bool objectInView = !a.focus.infinity && a.focus.objectZ - front <= 2 * span;
        setup.startZ = objectInView ? a.focus.objectZ + 0.04 * span : front + 0.45 * span;
    } else {
        pic.view = axialView(a, outline, markers, filmHalf, pic.content);
        setup.startZ = pic.view.zAt(pic.content.left);
    }
    if (a.lens.hasMirrors()) setup.bores = findMirrorBores(a.lens, layout, passingLightPaths(a, setup));
    outline = buildLensOutline(a.lens, layout, setup.bores);
    // Thick-lens rays first, so in overlay the real rays lie on top and the approximation shows
    // where it departs from them. A folded lens gets none (the legend says so).
    if (options.mode != DiagramMode::Exact && !a.lens.hasMirrors()) pic.rays = traceRayFans(a, RayModel::Thick, setup);
    if (options.mode != DiagramMode::Thick) {
        std::vector<FanRay> exact = options.colourFans ? traceColourFans(a, setup) : traceRayFans(a, RayModel::Exact, setup);
        pic.rays.insert(pic.rays.end(), exact.begin(), exact.end());
    }
    std::vector<ZY> foldedAxis;
    if (laidOut) {
        std::vector<ZY> drawn = outline.points();
        for (double y : {filmHalf, -filmHalf}) drawn.push_back(layout.inImageSpace(y, filmZ));
        for (const FanRay& ray : pic.rays) drawn.insert(drawn.end(), ray.points.begin(), ray.points.end());
        pic.view = laidOut->fit(drawn, markers, layout, planeHalf, pic.content);
        foldedAxis = opticalAxisPath(a, setup);
    }

    c.glass(outline);
    const double zLeftEdge = pic.view.zAt(pic.content.left), zRightEdge = pic.view.zAt(pic.content.right);
    int offLeft = 0, offRight = 0;
    std::vector<const Marker*> shown;
    auto spaceOf = [&](const Marker& m) { return m.imageSide ? layout.imageSpace : RigidMotion{}; };
    for (const Marker& m : markers) {
        const ZY where = LensLayout::place(spaceOf(m), {0, 0, m.z});
        const double y = pic.view.toPicture(where).y;
        const bool inView = where.z <= zLeftEdge && where.z >= zRightEdge && (!laidOut || (y >= pic.content.top && y <= pic.content.bottom));
        if (inView) shown.push_back(&m);
        else c.offPicture(where, m.z, m.name, where.z > zLeftEdge ? offLeft++ : offRight++);
    }
    for (const Marker* m : shown)
        if (m->kind == Marker::PrincipalPlane) c.principalPlane(spaceOf(*m), m->z, planeHalf, m->name);
    c.axis(foldedAxis);
    c.lensLines(outline);
    c.mirrors(outline);
    c.stop(outline.stop);
    c.film(layout.imageSpace, filmZ, filmHalf);
    c.rays(pic.rays);
    for (const Marker* m : shown) {
        if (m->kind == Marker::FocalPoint) c.focalPoint(spaceOf(*m), m->z, m->name);
        if (m->kind == Marker::Pupil) c.pupil(spaceOf(*m), m->z, m->diameter, m->name);
    }
    c.caption(lensName, filmZ, layout.moved);
    c.legend();
    return pic;
}

}  // namespace lenslab
