#include "prescription/ZemaxFile.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <unordered_map>
#include <vector>

#include "prescription/TextEncoding.h"
#include "prescription/Wavelength.h"

namespace lenslab {

namespace {

const char* const kSupported =
    "lenslab reads sequential, rotationally symmetric systems of STANDARD and EVENASPH surfaces";

// Zemax writes every one of its 24 wavelength slots; the unused ones hold this default.
constexpr int kWavelengthSlots = 24;
constexpr double kDefaultSlotMicrometres = 0.55;

struct Line {
    int number = 0;
    std::string keyword;
    std::vector<std::string> fields;
    std::string rest;  // the text after the keyword, for NAME and NOTE
};

// One SURF block as written: lengths in the file's unit, converted when the whole file is read
// (UNIT may come anywhere).
struct RawSurface {
    int line = 0;
    std::string type = "STANDARD";
    int curvatureLine = 0;  // 0: no CURV
    // Kept in long double: the radius is 1 / CURV, and a radius written as its curvature to 21
    // digits (formats/ZemaxWriter.cpp) then reads back as the same double.
    long double curvature = 0;
    int thicknessLine = 0;
    double thickness = 0;  // may be infinite (object surface only)
    double conic = 0;
    struct Term { int index; double value; int line; };
    std::vector<Term> parms;  // PARM lines; their meaning depends on the type
    std::string glass;        // catalog name, empty for air and model glasses
    bool mirror = false;
    double nd = 0, vd = 0;    // the GLAS line's figures
    bool modelGlass = false;
    double semiDiameter = 0, mechanicalSemiDiameter = 0;
    double apertureRadius = 0;     // CLAP/FLAP maximum radius; 0: none
    double obscurationRadius = 0;  // OBSC, or CLAP's minimum radius
    int stopLine = 0;
};

struct Wavelength { double micrometres; double weight; int line; };

struct Reader {
    std::string name;
    double millimetresPerUnit = 1;
    std::string title;  // NAME
    std::vector<std::string> notes;
    std::vector<Wavelength> wavelengths;
    int primarySlot = 1, primaryLine = 0;
    double enpd = 0, fnum = 0;
    std::vector<std::string> catalogs;
    std::vector<RawSurface> surfaces;
    int stopLine = 0;

    [[noreturn]] void fail(int line, const std::string& problem) const { throw LensTableError(name, line, problem); }

    RawSurface& surface(const Line& l) {
        if (surfaces.empty()) fail(l.number, l.keyword + " before the first SURF: it describes a surface");
        return surfaces.back();
    }

    const std::string& field(const Line& l, std::size_t i) const {
        if (i >= l.fields.size())
            fail(l.number, l.keyword + " needs at least " + std::to_string(i + 1) + " value(s) after it");
        return l.fields[i];
    }

    // Field i as a finite number. Tiny values that underflow are kept (as 0 or subnormal).
    double number(const Line& l, std::size_t i) const {
        const std::string& f = field(l, i);
        char* end = nullptr;
        const double v = std::strtod(f.c_str(), &end);
        if (end == f.c_str() || *end != '\0' || !std::isfinite(v))
            fail(l.number, l.keyword + " value " + std::to_string(i + 1) + " is not a finite number: '" + f + "'");
        return v;
    }

    int integer(const Line& l, std::size_t i) const {
        const double v = number(l, i);
        if (v != std::floor(v) || std::fabs(v) > 1e6)
            fail(l.number, l.keyword + " value " + std::to_string(i + 1) + " must be a whole number, found '" +
                               l.fields[i] + "'");
        return int(v);
    }
};

// ---- header lines ------------------------------------------------------------------------------

void readMode(Reader& r, const Line& l) {
    if (r.field(l, 0) != "SEQ")
        r.fail(l.number, "MODE " + l.fields[0] + ": only sequential files (MODE SEQ) are read; " + kSupported);
}

void readUnit(Reader& r, const Line& l) {
    static const std::unordered_map<std::string, double> units = {{"MM", 1}, {"CM", 10}, {"IN", 25.4}, {"M", 1000}};
    const auto it = units.find(r.field(l, 0));
    if (it == units.end()) r.fail(l.number, "UNIT " + l.fields[0] + " is not one of MM, CM, IN, M");
    r.millimetresPerUnit = it->second;
}

std::string trimmed(const std::string& s) {
    const auto b = s.find_first_not_of(" \t");
    return b == std::string::npos ? "" : s.substr(b, s.find_last_not_of(" \t") - b + 1);
}

void readName(Reader& r, const Line& l) { r.title = trimmed(l.rest); }

// NOTE n text: n is Zemax's note slot, the text a line of the designer's notes.
void readNote(Reader& r, const Line& l) {
    std::istringstream in(l.rest);
    std::string slot;
    in >> slot;
    std::string text;
    std::getline(in, text);
    if (!trimmed(text).empty()) r.notes.push_back(trimmed(text));
}

void readEnpd(Reader& r, const Line& l) { r.enpd = r.number(l, 0); }
void readFnum(Reader& r, const Line& l) { r.fnum = r.number(l, 0); }
void readGcat(Reader& r, const Line& l) { r.catalogs.insert(r.catalogs.end(), l.fields.begin(), l.fields.end()); }

// WAVM slot micrometres weight
void readWavm(Reader& r, const Line& l) {
    const int slot = r.integer(l, 0);
    if (slot != int(r.wavelengths.size()) + 1)
        r.fail(l.number, "WAVM " + l.fields[0] + " out of order: expected slot " +
                             std::to_string(r.wavelengths.size() + 1));
    r.wavelengths.push_back({r.number(l, 1), l.fields.size() > 2 ? r.number(l, 2) : 1.0, l.number});
}

void readPwav(Reader& r, const Line& l) {
    r.primarySlot = r.integer(l, 0);
    r.primaryLine = l.number;
}

void readSurf(Reader& r, const Line& l) {
    const int n = r.integer(l, 0);
    if (n != int(r.surfaces.size()))
        r.fail(l.number, "SURF " + l.fields[0] + " out of order: expected SURF " + std::to_string(r.surfaces.size()));
    // Object + kMaxLensSurfaces lens surfaces + image.
    if (n > kMaxLensSurfaces + 1)
        r.fail(l.number, "too many surfaces: a lens may have at most " + std::to_string(kMaxLensSurfaces) +
                             " surfaces between the object and the image");
    r.surfaces.emplace_back();
    r.surfaces.back().line = l.number;
}

// ---- surface lines -----------------------------------------------------------------------------

void readType(Reader& r, const Line& l) {
    const std::string& type = r.field(l, 0);
    if (type == "COORDBRK")
        r.fail(l.number, "coordinate breaks (TYPE COORDBRK: tilts and decenters) are not supported; " +
                             std::string(kSupported) + " on one axis");
    if (type.rfind("GRIN", 0) == 0)
        r.fail(l.number, "gradient-index surfaces (TYPE " + type + ") are not supported; " + kSupported +
                             " with homogeneous glass");
    if (type == "ODDASPHE")
        r.fail(l.number, "odd aspheres (TYPE ODDASPHE) are not supported; " + std::string(kSupported) +
                             " (even aspheres: r^2 .. r^16)");
    if (type != "STANDARD" && type != "EVENASPH")
        r.fail(l.number, "surface type " + type + " is not supported; " + kSupported);
    r.surface(l).type = type;
}

void readCurv(Reader& r, const Line& l) {
    RawSurface& s = r.surface(l);
    r.number(l, 0);  // a finite number
    s.curvature = std::strtold(l.fields[0].c_str(), nullptr);
    s.curvatureLine = l.number;
}

void readDisz(Reader& r, const Line& l) {
    RawSurface& s = r.surface(l);
    s.thickness = r.field(l, 0) == "INFINITY" ? INFINITY : r.number(l, 0);
    s.thicknessLine = l.number;
}

void readConi(Reader& r, const Line& l) { r.surface(l).conic = r.number(l, 0); }

void readParm(Reader& r, const Line& l) { r.surface(l).parms.push_back({r.integer(l, 0), r.number(l, 1), l.number}); }

// GLAS name solve pickup nd vd ...: solve 1 makes (nd, vd) a model glass, as does the name ___BLANK
// (Zemax's model glass, also when picked up, solve 2); otherwise the name is a catalog glass and nd
// its index at d where the file gives one.
void readGlas(Reader& r, const Line& l) {
    RawSurface& s = r.surface(l);
    const std::string& name = r.field(l, 0);
    if (name == "MIRROR") {
        s.mirror = true;
        return;
    }
    s.nd = l.fields.size() > 3 ? r.number(l, 3) : 0;
    s.vd = l.fields.size() > 4 ? r.number(l, 4) : 0;
    s.modelGlass = name == "___BLANK" || (l.fields.size() > 1 && r.integer(l, 1) == 1);
    s.glass = s.modelGlass ? "" : name;
    if (s.modelGlass && (l.fields.size() < 5 || s.nd < 1 || s.vd < 0))
        r.fail(l.number, "a model glass needs nd >= 1 and Vd >= 0 (GLAS ___BLANK solve pickup nd Vd)");
    if (s.nd != 0 && s.nd < 1) r.fail(l.number, "GLAS " + name + ": nd " + l.fields[3] + " is below 1");
}

void readDiam(Reader& r, const Line& l) { r.surface(l).semiDiameter = r.number(l, 0); }
void readMema(Reader& r, const Line& l) { r.surface(l).mechanicalSemiDiameter = r.number(l, 0); }

void readStop(Reader& r, const Line& l) {
    r.surface(l);
    if (r.stopLine) r.fail(l.number, "a second STOP; the first is on line " + std::to_string(r.stopLine));
    r.stopLine = r.surfaces.back().stopLine = l.number;
}

// CLAP/FLAP minRadius maxRadius: a circular aperture; a minimum radius blocks the centre.
void readCircularAperture(Reader& r, const Line& l) {
    RawSurface& s = r.surface(l);
    s.obscurationRadius = r.number(l, 0);
    s.apertureRadius = r.number(l, 1);
    if (s.apertureRadius <= 0 || s.obscurationRadius < 0 || s.obscurationRadius >= s.apertureRadius)
        r.fail(l.number, l.keyword + " needs 0 <= minimum radius < maximum radius, found " + l.fields[0] + " " +
                             l.fields[1]);
}

// OBSC minRadius maxRadius: a central obscuration when the minimum is 0.
void readObsc(Reader& r, const Line& l) {
    RawSurface& s = r.surface(l);
    if (r.number(l, 0) != 0)
        r.fail(l.number,
               "annular obscurations (OBSC with a minimum radius) are not supported; only central ones (OBSC 0 radius)");
    s.obscurationRadius = r.number(l, 1);
    if (s.obscurationRadius < 0) r.fail(l.number, "OBSC radius must not be negative, found " + l.fields[1]);
}

// Lines that move a surface or its aperture off the axis: refused unless every value is 0.
void refuseIfNonZero(Reader& r, const Line& l, std::size_t firstValue, const std::string& what) {
    r.surface(l);
    for (std::size_t i = firstValue; i < l.fields.size(); ++i)
        if (r.number(l, i) != 0)
            r.fail(l.number, what + " (" + l.keyword + ") are not supported; " + kSupported + " on one axis");
}

void readDecenterOrTilt(Reader& r, const Line& l) { refuseIfNonZero(r, l, 0, "tilts and decenters"); }
// SCBD flag order decenters... tilts...
void readScbd(Reader& r, const Line& l) { refuseIfNonZero(r, l, 2, "surface tilts and decenters"); }
void readObdc(Reader& r, const Line& l) { refuseIfNonZero(r, l, 0, "decentered apertures"); }

void refuseGrin(Reader& r, const Line& l) {
    r.fail(l.number,
           "gradient-index media (GRIN) are not supported; " + std::string(kSupported) + " with homogeneous glass");
}

void refuseNonCircularAperture(Reader& r, const Line& l) {
    r.fail(l.number, "rectangular and elliptical apertures (" + l.keyword +
                         ") are not supported; apertures are circular (DIAM, CLAP, FLAP, OBSC)");
}

using Handler = void (*)(Reader&, const Line&);

// Every keyword that changes what lenslab builds; all others (FIMP, HIDE, MIRR, SLAB, POPS, COFN,
// display and optimisation settings, pickups whose values Zemax also writes resolved) are ignored.
const std::unordered_map<std::string, Handler>& handlers() {
    static const std::unordered_map<std::string, Handler> table = {
        {"MODE", readMode}, {"UNIT", readUnit}, {"NAME", readName}, {"NOTE", readNote},
        {"ENPD", readEnpd}, {"FNUM", readFnum}, {"GCAT", readGcat}, {"WAVM", readWavm},
        {"PWAV", readPwav}, {"SURF", readSurf}, {"TYPE", readType}, {"CURV", readCurv},
        {"DISZ", readDisz}, {"CONI", readConi}, {"PARM", readParm}, {"GLAS", readGlas},
        {"DIAM", readDiam}, {"MEMA", readMema}, {"STOP", readStop}, {"CLAP", readCircularAperture},
        {"FLAP", readCircularAperture}, {"OBSC", readObsc}, {"DECX", readDecenterOrTilt},
        {"DECY", readDecenterOrTilt}, {"TILT", readDecenterOrTilt}, {"SCBD", readScbd},
        {"OBDC", readObdc}, {"GRIN", refuseGrin}, {"SQAP", refuseNonCircularAperture},
        {"ELAP", refuseNonCircularAperture},
    };
    return table;
}

Line splitLine(const std::string& text, int number) {
    Line l;
    l.number = number;
    std::istringstream in(text);
    in >> l.keyword;
    const auto after = text.find(l.keyword) + l.keyword.size();
    l.rest = text.substr(after);
    for (std::string f; in >> f;) l.fields.push_back(f);
    return l;
}

// ---- assembly ----------------------------------------------------------------------------------

// Even-asphere PARM i is the coefficient of r^(2i): in mm it scales as length^(1-2i).
AsphericCoefficients asphericTerms(const Reader& r, const RawSurface& s) {
    AsphericCoefficients a{};
    if (s.type != "EVENASPH") return a;  // a STANDARD surface has no parameters: Zemax keeps stale ones
    for (const auto& t : s.parms) {
        if (t.index < 1 || t.index > kAsphericTerms) {
            if (t.value != 0)
                r.fail(t.line, "EVENASPH has PARM 1..8 (r^2 .. r^16); PARM " + std::to_string(t.index) + " is not one");
            continue;
        }
        a[t.index - 1] = t.value * std::pow(r.millimetresPerUnit, 1 - 2 * t.index);
        if (!std::isfinite(a[t.index - 1])) r.fail(t.line, "PARM value is not finite in millimetres");
    }
    return a;
}

// The medium after surface s: a mirror sends the ray back through the medium it came from.
void setMedium(LensTableRow& row, const RawSurface& s, const LensTableRow* before) {
    row.mirror = s.mirror;
    if (s.mirror) {
        if (before) {
            row.index = before->index;
            row.glass = before->glass;
            row.abbe = before->abbe;
        }
        return;
    }
    row.index = s.nd;
    row.glass = s.glass;
    row.abbe = s.modelGlass ? s.vd : 0;
}

LensTableRow lensRow(const Reader& r, const RawSurface& s, int number, const LensTableRow* before, bool reversed) {
    const double u = r.millimetresPerUnit;
    LensTableRow row;
    row.line = s.line;
    row.stop = s.stopLine != 0;
    if (s.curvature != 0) row.radius = static_cast<double>(u / s.curvature);
    if (!std::isfinite(row.radius)) r.fail(s.curvatureLine, "CURV is too small: the radius is not a finite number of mm");
    if (!s.thicknessLine) r.fail(s.line, "SURF " + std::to_string(number) + " has no DISZ (thickness to the next surface)");
    row.gap = s.thickness * u;
    if (!std::isfinite(row.gap))
        r.fail(s.thicknessLine, "DISZ must be a finite thickness (INFINITY only on the object surface, SURF 0)");
    if (row.gap < 0 && !reversed)
        r.fail(s.thicknessLine, "negative thickness " + formatNumber(s.thickness) +
                                    " where the light travels toward the image: a negative DISZ is allowed only after a mirror");
    setMedium(row, s, before);
    row.conic = s.conic;
    row.aspheric = asphericTerms(r, s);
    // The clear aperture is DIAM (Zemax's semi-diameter); a circular aperture overrides it, and the
    // mechanical semi-diameter stands in where DIAM is 0.
    const double semi = s.apertureRadius > 0 ? s.apertureRadius
                        : s.semiDiameter > 0 ? s.semiDiameter
                                             : s.mechanicalSemiDiameter;
    row.diameter = 2 * semi * u;
    row.obscurationDiameter = 2 * s.obscurationRadius * u;
    if (!(row.diameter > 0) || !std::isfinite(row.diameter))
        r.fail(s.line, "SURF " + std::to_string(number) + " has no positive semi-diameter (DIAM, MEMA, CLAP or FLAP)");
    if (row.obscurationDiameter >= row.diameter)
        r.fail(s.line, "SURF " + std::to_string(number) + ": the obscuration covers the whole clear aperture");
    return row;
}

// Zemax lists all 24 wavelength slots; trailing default slots past the primary are unused ones.
std::vector<Wavelength> usedWavelengths(const Reader& r) {
    std::vector<Wavelength> w = r.wavelengths;
    if (int(w.size()) == kWavelengthSlots)
        while (int(w.size()) > std::max(r.primarySlot, 1) && w.back().micrometres == kDefaultSlotMicrometres &&
               w.back().weight == 1)
            w.pop_back();
    return w;
}

void setHeader(const Reader& r, LensTable& t) {
    t.name = r.name;
    t.layout = TableLayout::GapAfter;
    t.format = "zmx";
    if (!r.title.empty()) t.comments.push_back(r.title);
    t.comments.insert(t.comments.end(), r.notes.begin(), r.notes.end());
    // Long notes (licences, disclaimers) are cut at the bound rather than refusing the lens.
    std::size_t kept = 0, bytes = 0;
    while (kept < t.comments.size() && (bytes += t.comments[kept].size()) <= kMaxCommentBytes) ++kept;
    t.comments.resize(kept);
    for (const Wavelength& w : usedWavelengths(r)) {
        if (const auto problem = wavelengthProblem(w.micrometres * 1000)) r.fail(w.line, "WAVM: " + *problem);
        t.wavelengths.push_back(w.micrometres * 1000);
    }
    if (!t.wavelengths.empty()) {
        if (r.primarySlot < 1 || r.primarySlot > int(t.wavelengths.size()))
            r.fail(r.primaryLine, "PWAV " + std::to_string(r.primarySlot) + " names no WAVM wavelength (1.." +
                                      std::to_string(t.wavelengths.size()) + ")");
        t.primaryWavelength = t.wavelengths[r.primarySlot - 1];
    }
    t.catalogs = r.catalogs;
    if (r.fnum > 0) t.designFNumber = r.fnum;
    if (r.enpd > 0) t.entrancePupilDiameter = r.enpd * r.millimetresPerUnit;
}

LensTable assemble(const Reader& r, int lastLine) {
    const int n = int(r.surfaces.size());
    if (n < 3)
        r.fail(std::max(lastLine, 1), "no lens surfaces: a .zmx needs SURF blocks for the object, at least one lens surface and the image");
    const RawSurface& object = r.surfaces.front();
    const RawSurface& image = r.surfaces.back();
    if (object.stopLine) r.fail(object.stopLine, "the object surface (SURF 0) cannot be the stop");
    if (image.stopLine) r.fail(image.stopLine, "the image surface cannot be the stop");
    if (!r.stopLine) r.fail(object.line, "no STOP: one lens surface must be marked STOP (the aperture stop)");
    for (std::size_t i = 0; i < r.surfaces.size(); ++i)
        if (!r.surfaces[i].curvatureLine)
            r.fail(r.surfaces[i].line, "SURF " + std::to_string(i) + " has no CURV (curvature; 0 for flat)");
    LensTable t;
    setHeader(r, t);
    bool reversed = false;  // after an odd number of mirrors the light runs back toward the object
    for (int i = 1; i + 1 < n; ++i) {
        reversed ^= r.surfaces[i].mirror;
        t.rows.push_back(lensRow(r, r.surfaces[i], i, t.rows.empty() ? nullptr : &t.rows.back(), reversed));
    }
    return t;
}

std::vector<std::string> splitLines(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string l; std::getline(in, l);) {
        if (!l.empty() && l.back() == '\r') l.pop_back();
        lines.push_back(l);
    }
    return lines;
}

}  // namespace

LensTable parseZemax(const std::string& bytes, const std::string& name) {
    Reader r;
    r.name = name;
    const auto lines = splitLines(toUtf8Text(bytes, name));
    bool empty = true;
    for (std::size_t i = 0; i < lines.size(); ++i) {
        const Line l = splitLine(lines[i], int(i) + 1);
        if (l.keyword.empty()) continue;
        empty = false;
        if (auto h = handlers().find(l.keyword); h != handlers().end()) h->second(r, l);
    }
    if (empty) r.fail(1, "empty file: no Zemax lines");
    return assemble(r, int(lines.size()));
}

bool looksLikeZemax(const std::string& bytes) {
    if (startsWithUtf16ByteOrderMark(bytes)) return true;
    std::istringstream in(bytes.rfind("\xef\xbb\xbf", 0) == 0 ? bytes.substr(3) : bytes);
    for (std::string line; std::getline(in, line);) {
        std::istringstream words(line);
        std::string first;
        if (!(words >> first)) continue;
        for (const char* k : {"VERS", "MODE", "NAME", "NOTE", "UNIT", "SURF"})
            if (first == k) return true;
        return false;
    }
    return false;
}

}  // namespace lenslab
