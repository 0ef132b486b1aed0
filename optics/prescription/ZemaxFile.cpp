#include "prescription/ZemaxFile.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <sstream>
#include <unordered_map>
#include <vector>

#include "prescription/Coating.h"
#include "prescription/NumberText.h"
#include "prescription/TextEncoding.h"
#include "prescription/Wavelength.h"

namespace lenslab {

namespace {

const char* const kSupported =
    "lenslab reads sequential systems of STANDARD, EVENASPH, ODDASPH, QTYPE/QED_TYPE, TOROIDAL and COORDBRK surfaces";

// Zemax writes every one of its 24 wavelength slots; the unused ones hold this default.
constexpr int kWavelengthSlots = 24;
constexpr double kDefaultSlotNanometres = 550;

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
    int semiDiameterLine = 0;      // 0: no DIAM
    double apertureRadius = 0;     // CLAP/FLAP maximum radius; 0: none
    double obscurationRadius = 0;  // OBSC, or CLAP's minimum radius
    int stopLine = 0;
    std::vector<Term> extra;       // XDAT lines (Q-type data)
    std::optional<SurfaceAperture> clearShape, obscurationShape;  // SQAP/ELAP, SQOB/ELOB (file units)
    double apertureCentreX = 0, apertureCentreY = 0;            // OBDC
    std::optional<FrameChange> tilt;  // SCBD: this surface's own decentre and tilt
    std::string comment;              // COMM
    std::string coating;           // COAT, as written
};

struct Wavelength { double nanometres; double weight; int line; };

struct Fields {
    int type = 0;
    int count = -1;        // FTYP's field count; -1: no FTYP
    int wavelengths = -1;  // FTYP's wavelength count
    std::vector<double> x, y, weights;
};

struct ZmxReader {
    std::string name;
    double millimetresPerUnit = 1;
    std::string title;  // NAME
    std::vector<std::string> notes;
    std::vector<Wavelength> wavelengths;
    int primarySlot = 1, primaryLine = 0;
    double enpd = 0, fnum = 0, obna = 0;
    Fields fields;
    std::vector<std::string> catalogs;
    std::vector<RawSurface> surfaces;
    int stopLine = 0;
    std::vector<LensWarning> warnings;

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

void readMode(ZmxReader& r, const Line& l) {
    if (r.field(l, 0) != "SEQ")
        r.fail(l.number, "MODE " + l.fields[0] + ": only sequential files (MODE SEQ) are read; " + kSupported);
}

void readUnit(ZmxReader& r, const Line& l) {
    static const std::unordered_map<std::string, double> units = {{"MM", 1}, {"CM", 10}, {"IN", 25.4}, {"M", 1000}};
    const auto it = units.find(r.field(l, 0));
    if (it == units.end()) r.fail(l.number, "UNIT " + l.fields[0] + " is not one of MM, CM, IN, M");
    r.millimetresPerUnit = it->second;
}

std::string trimmed(const std::string& s) {
    const auto b = s.find_first_not_of(" \t");
    return b == std::string::npos ? "" : s.substr(b, s.find_last_not_of(" \t") - b + 1);
}

void readName(ZmxReader& r, const Line& l) { r.title = trimmed(l.rest); }

// NOTE n text: n is Zemax's note slot, the text a line of the designer's notes.
void readNote(ZmxReader& r, const Line& l) {
    std::istringstream in(l.rest);
    std::string slot;
    in >> slot;
    std::string text;
    std::getline(in, text);
    if (!trimmed(text).empty()) r.notes.push_back(trimmed(text));
}

void readEnpd(ZmxReader& r, const Line& l) { r.enpd = r.number(l, 0); }
void readFnum(ZmxReader& r, const Line& l) { r.fnum = r.number(l, 0); }
void readObna(ZmxReader& r, const Line& l) { r.obna = r.number(l, 0); }

// FTYP type ? fields wavelengths ...: type 0 angle, 1 object height, 2 paraxial and 3 real image height.
void readFtyp(ZmxReader& r, const Line& l) {
    r.fields.type = r.integer(l, 0);
    if (r.fields.type < 0 || r.fields.type > 3)
        r.fail(l.number, "FTYP " + l.fields[0] + ": lenslab reads field types 0 to 3 (angle, object height, paraxial "
                                                 "and real image height)");
    if (l.fields.size() > 2) r.fields.count = r.integer(l, 2);
    if (l.fields.size() > 3) r.fields.wavelengths = r.integer(l, 3);
}

void readFieldValues(ZmxReader& r, const Line& l) {
    std::vector<double> v;
    for (std::size_t i = 0; i < l.fields.size(); ++i) v.push_back(r.number(l, i));
    (l.keyword == "XFLN" ? r.fields.x : l.keyword == "YFLN" ? r.fields.y : r.fields.weights) = v;
}
void readGcat(ZmxReader& r, const Line& l) { r.catalogs.insert(r.catalogs.end(), l.fields.begin(), l.fields.end()); }

// The number a decimal text in micrometres states, in nanometres: the text read with its exponent
// raised by 3, so "0.5875618" is exactly the double "587.5618" is (a double read in micrometres,
// times 1000, misses some by an ulp; formats/ZemaxWriter.cpp writes wavelengths this way).
double nanometres(const ZmxReader& r, const Line& l, std::size_t i) {
    const double micrometres = r.number(l, i);  // a finite number
    const std::string& text = l.fields[i];
    const auto e = text.find_first_of("eE");
    if (e == std::string::npos) return std::strtod((text + "e3").c_str(), nullptr);
    // An exponent of many digits (0.5e-99999999999999999999 is a finite 0) is no wavelength to keep
    // exact: the range check refuses it, and its own sum could overflow.
    const long exponent = std::strtol(text.c_str() + e + 1, nullptr, 10);
    if (exponent > 1000 || exponent < -1000) return micrometres * 1000;
    return std::strtod((text.substr(0, e) + "e" + std::to_string(exponent + 3)).c_str(), nullptr);
}

// WAVM slot micrometres weight
void readWavm(ZmxReader& r, const Line& l) {
    const int slot = r.integer(l, 0);
    if (slot != int(r.wavelengths.size()) + 1)
        r.fail(l.number, "WAVM " + l.fields[0] + " out of order: expected slot " +
                             std::to_string(r.wavelengths.size() + 1));
    r.wavelengths.push_back({nanometres(r, l, 1), l.fields.size() > 2 ? r.number(l, 2) : 1.0, l.number});
}

void readPwav(ZmxReader& r, const Line& l) {
    r.primarySlot = r.integer(l, 0);
    r.primaryLine = l.number;
}

void readSurf(ZmxReader& r, const Line& l) {
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

void readType(ZmxReader& r, const Line& l) {
    std::string type = r.field(l, 0);
    if (type.rfind("GRIN", 0) == 0)
        r.fail(l.number, "gradient-index surfaces (TYPE " + type + ") are not supported; " + kSupported +
                             " with homogeneous glass");
    if (type == "ODDASPHE") type = "ODDASPH";
    if (type == "QTYPE") type = "QED_TYPE";
    if (type != "STANDARD" && type != "EVENASPH" && type != "ODDASPH" && type != "QED_TYPE" && type != "COORDBRK" &&
        type != "TOROIDAL")
        r.fail(l.number, "surface type " + type + " is not supported; " + kSupported);
    r.surface(l).type = type;
}

void readCurv(ZmxReader& r, const Line& l) {
    RawSurface& s = r.surface(l);
    r.number(l, 0);  // a finite number
    s.curvature = std::strtold(l.fields[0].c_str(), nullptr);
    s.curvatureLine = l.number;
}

void readDisz(ZmxReader& r, const Line& l) {
    RawSurface& s = r.surface(l);
    s.thickness = r.field(l, 0) == "INFINITY" ? INFINITY : r.number(l, 0);
    s.thicknessLine = l.number;
}

void readConi(ZmxReader& r, const Line& l) { r.surface(l).conic = r.number(l, 0); }

void readParm(ZmxReader& r, const Line& l) { r.surface(l).parms.push_back({r.integer(l, 0), r.number(l, 1), l.number}); }
void readXdat(ZmxReader& r, const Line& l) { r.surface(l).extra.push_back({r.integer(l, 0), r.number(l, 1), l.number}); }
void readComm(ZmxReader& r, const Line& l) { r.surface(l).comment = trimmed(l.rest); }

// GLAS name solve pickup nd vd ...: solve 1 makes (nd, vd) a model glass, as does the name ___BLANK
// (Zemax's model glass, also when picked up, solve 2); otherwise the name is a catalog glass and nd
// its index at d where the file gives one.
void readGlas(ZmxReader& r, const Line& l) {
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

// COAT name: lenslab's coating text (prescription/Coating.h), which covers the names of single
// materials Zemax uses (MGF2). A coating defined only in a COATING.DAT file (a vendor's THORC)
// leaves the surface with the default coating and a warning: it changes ghosts, not the image.
void readCoat(ZmxReader& r, const Line& l) {
    RawSurface& s = r.surface(l);
    s.coating = trimmed(l.rest);
    if (s.coating.empty()) return;  // a blank coating column
    try {
        parseCoating(s.coating);
    } catch (const CoatingError& e) {
        r.warnings.push_back({l.number, "coating " + s.coating.substr(0, 40) + " is not one lenslab knows (" + e.what() +
                                            "; it does not read Zemax's COATING.DAT): the default coating stands in"});
        s.coating.clear();
    }
}

void readDiam(ZmxReader& r, const Line& l) {
    RawSurface& s = r.surface(l);
    s.semiDiameter = r.number(l, 0);
    s.semiDiameterLine = l.number;
}
void readMema(ZmxReader& r, const Line& l) { r.surface(l).mechanicalSemiDiameter = r.number(l, 0); }

void readStop(ZmxReader& r, const Line& l) {
    r.surface(l);
    if (r.stopLine) r.fail(l.number, "a second STOP; the first is on line " + std::to_string(r.stopLine));
    r.stopLine = r.surfaces.back().stopLine = l.number;
}

// CLAP/FLAP minRadius maxRadius: a circular aperture; a minimum radius blocks the centre.
void readCircularAperture(ZmxReader& r, const Line& l) {
    RawSurface& s = r.surface(l);
    s.obscurationRadius = r.number(l, 0);
    s.apertureRadius = r.number(l, 1);
    if (s.apertureRadius <= 0 || s.obscurationRadius < 0 || s.obscurationRadius >= s.apertureRadius)
        r.fail(l.number, l.keyword + " needs 0 <= minimum radius < maximum radius, found " + l.fields[0] + " " +
                             l.fields[1]);
}

// OBSC minRadius maxRadius: a central obscuration when the minimum is 0.
void readObsc(ZmxReader& r, const Line& l) {
    RawSurface& s = r.surface(l);
    if (r.number(l, 0) != 0)
        r.fail(l.number,
               "annular obscurations (OBSC with a minimum radius) are not supported; only central ones (OBSC 0 radius)");
    s.obscurationRadius = r.number(l, 1);
    if (s.obscurationRadius < 0) r.fail(l.number, "OBSC radius must not be negative, found " + l.fields[1]);
}

// The old form of surface tilts (DECX, DECY, TILT): refused unless every value is 0.
void readDecenterOrTilt(ZmxReader& r, const Line& l) {
    r.surface(l);
    for (std::size_t i = 0; i < l.fields.size(); ++i)
        if (r.number(l, i) != 0)
            r.fail(l.number, "tilts and decenters in the old form (" + l.keyword +
                                 ") are not supported; give them as SCBD or coordinate breaks (COORDBRK)");
}

// SCBD 1 order ? dx dy tiltx tilty tiltz: the surface's own decentre and tilt, before it (the
// coordinates return after it). Other SCBD lines (the after-surface data) must be all zero.
void readScbd(ZmxReader& r, const Line& l) {
    RawSurface& s = r.surface(l);
    const int which = r.integer(l, 0);
    std::array<double, 5> v{};
    for (std::size_t i = 0; i < v.size(); ++i) v[i] = l.fields.size() > 3 + i ? r.number(l, 3 + i) : 0;
    if (which != 1) {
        for (double x : v)
            if (x != 0) r.fail(l.number, "SCBD " + l.fields[0] + ": only the before-surface tilt and decentre (SCBD 1) is read");
        return;
    }
    FrameChange f;
    f.decentre = {v[0], v[1], 0};
    f.tiltDegrees = {v[2], v[3], v[4]};
    f.mode = FrameMode::DecentreAndReturn;
    f.order = l.fields.size() > 1 && r.integer(l, 1) != 0 ? TiltOrder::TiltThenDecentre : TiltOrder::DecentreThenTilt;
    if (!f.isIdentity()) s.tilt = f;
}

// OBDC x y: the aperture's decentre in the surface's plane.
void readObdc(ZmxReader& r, const Line& l) {
    RawSurface& s = r.surface(l);
    s.apertureCentreX = r.number(l, 0);
    s.apertureCentreY = l.fields.size() > 1 ? r.number(l, 1) : 0;
}

void refuseGrin(ZmxReader& r, const Line& l) {
    r.fail(l.number,
           "gradient-index media (GRIN) are not supported; " + std::string(kSupported) + " with homogeneous glass");
}

// SQAP/ELAP xhalf yhalf: a rectangular or elliptical clear aperture; SQOB/ELOB the obscuration.
void readShapedAperture(ZmxReader& r, const Line& l) {
    RawSurface& s = r.surface(l);
    SurfaceAperture a;
    a.kind = l.keyword[0] == 'S' ? ApertureKind::Rectangular : ApertureKind::Elliptical;
    a.halfWidthX = r.number(l, 0);
    a.halfWidthY = r.number(l, 1);
    if (!(a.halfWidthX > 0 && a.halfWidthY > 0))
        r.fail(l.number, l.keyword + " needs two positive half widths, found " + l.fields[0] + " " + l.fields[1]);
    (l.keyword[2] == 'A' ? s.clearShape : s.obscurationShape) = a;
}

using Handler = void (*)(ZmxReader&, const Line&);

// Every keyword that changes what lenslab builds or the file's own analysis (its fields); all others
// (FIMP, HIDE, MIRR, SLAB, POPS, COFN, display and optimisation settings, pickups whose values Zemax
// also writes resolved) are ignored.
const std::unordered_map<std::string, Handler>& handlers() {
    static const std::unordered_map<std::string, Handler> table = {
        {"MODE", readMode}, {"UNIT", readUnit}, {"NAME", readName}, {"NOTE", readNote},
        {"ENPD", readEnpd}, {"FNUM", readFnum}, {"GCAT", readGcat}, {"WAVM", readWavm},
        {"PWAV", readPwav}, {"SURF", readSurf}, {"TYPE", readType}, {"CURV", readCurv},
        {"DISZ", readDisz}, {"CONI", readConi}, {"PARM", readParm}, {"GLAS", readGlas},
        {"DIAM", readDiam}, {"MEMA", readMema}, {"STOP", readStop}, {"CLAP", readCircularAperture},
        {"FLAP", readCircularAperture}, {"OBSC", readObsc}, {"DECX", readDecenterOrTilt},
        {"DECY", readDecenterOrTilt}, {"TILT", readDecenterOrTilt}, {"SCBD", readScbd},
        {"OBDC", readObdc}, {"GRIN", refuseGrin}, {"SQAP", readShapedAperture},
        {"ELAP", readShapedAperture}, {"SQOB", readShapedAperture}, {"ELOB", readShapedAperture},
        {"XDAT", readXdat}, {"COMM", readComm}, {"OBNA", readObna}, {"FTYP", readFtyp},
        {"XFLN", readFieldValues}, {"YFLN", readFieldValues}, {"FWGN", readFieldValues},
        {"COAT", readCoat},
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
AsphericCoefficients asphericTerms(const ZmxReader& r, const RawSurface& s) {
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

// ODDASPH PARM i multiplies r^i (i = 1..8): in mm it scales as length^(1-i). A Q-type surface's
// XDAT 1 is its kind (0 Qcon, 1 Qbfs; ASL5040-UV's conic base fixes 0 as Qcon, which Qbfs has not),
// XDAT 2 the number of terms, XDAT 3 the normalisation radius, XDAT 4.. the terms a_m (lengths).
SurfaceForm surfaceForm(const ZmxReader& r, const RawSurface& s) {
    const double u = r.millimetresPerUnit;
    SurfaceForm f;
    if (s.type == "ODDASPH") {
        f.kind = SurfaceKind::OddAsphere;
        for (const auto& t : s.parms) {
            if (t.index < 1 || t.index > kFormTerms) {
                if (t.value != 0) r.fail(t.line, "ODDASPH has PARM 1..16 (r^1 .. r^16); PARM " + std::to_string(t.index) + " is not one");
                continue;
            }
            f.terms[t.index - 1] = t.value * std::pow(u, 1 - t.index);
            f.termCount = std::max(f.termCount, t.value != 0 ? t.index : 0);
        }
    } else if (s.type == "TOROIDAL") {
        // PARM 1 the radius of rotation, PARM 2.. the y^2, y^4, ... terms; XDAT 1 counts extra terms.
        f.kind = SurfaceKind::Toroidal;
        for (const auto& t : s.parms) {
            if (t.index < 1 || t.index > kFormTerms) {
                if (t.value != 0) r.fail(t.line, "TOROIDAL has PARM 1..16; PARM " + std::to_string(t.index) + " is not one");
                continue;
            }
            f.terms[t.index - 1] = t.value * std::pow(u, t.index == 1 ? 1 : 1 - 2 * (t.index - 1));
            f.termCount = std::max(f.termCount, t.index);
        }
        for (const auto& t : s.extra)
            if (t.index == 1 && t.value != 0)
                r.fail(t.line, "the toroid's extra polynomial terms (XDAT 1 " + formatNumber(t.value) + ") are not supported");
    } else if (s.type == "QED_TYPE") {
        std::array<double, 3 + kFormTerms> x{};
        int count = 0;
        for (const auto& t : s.extra) {
            if (t.index < 1 || t.index > int(x.size()))
                r.fail(t.line, "XDAT " + std::to_string(t.index) + " lies beyond the " + std::to_string(kFormTerms) +
                                   " Q terms lenslab reads");
            x[t.index - 1] = t.value;
            count = std::max(count, t.index);
        }
        if (x[0] != 0 && x[0] != 1) r.fail(s.line, "the Q-type surface's XDAT 1 must be 0 (Qcon) or 1 (Qbfs)");
        f.kind = x[0] == 0 ? SurfaceKind::Qcon : SurfaceKind::Qbfs;
        if (!(x[1] >= 0 && x[1] <= kFormTerms) || x[1] != std::floor(x[1]))
            r.fail(s.line, "a Q-type surface's XDAT 2 counts its terms: a whole number up to " + std::to_string(kFormTerms) +
                               " here");
        f.termCount = std::min(int(x[1]), std::max(count - 3, 0));
        f.normalisationRadius = x[2] * u;
        for (int m = 0; m < f.termCount; ++m) f.terms[m] = x[3 + m] * u;
    }
    for (double v : f.terms)
        if (!std::isfinite(v)) r.fail(s.line, "a surface term is not finite in millimetres");
    return f;
}

// The medium after surface s: a mirror sends the ray back through the medium it came from, and a
// coordinate break leaves it as it was.
void setMedium(LensTableRow& row, const RawSurface& s, const LensTableRow* before) {
    row.mirror = s.mirror;
    if (s.mirror || s.type == "COORDBRK") {
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

// PARM 1, 2 decentre x, y; 3, 4, 5 tilt about x, y, z (degrees); 6 the order (0: decentre first).
FrameChange coordinateBreak(const ZmxReader& r, const RawSurface& s) {
    FrameChange f;
    for (const auto& t : s.parms) {
        if (t.index == 1 || t.index == 2) f.decentre[t.index - 1] = t.value * r.millimetresPerUnit;
        else if (t.index >= 3 && t.index <= 5) f.tiltDegrees[t.index - 3] = t.value;
        else if (t.index == 6) f.order = t.value != 0 ? TiltOrder::TiltThenDecentre : TiltOrder::DecentreThenTilt;
        else if (t.value != 0) r.fail(t.line, "COORDBRK has PARM 1..6; PARM " + std::to_string(t.index) + " is not one");
    }
    return f;
}

// A surface's own decentre, in millimetres.
std::optional<FrameChange> surfaceTilt(const ZmxReader& r, const RawSurface& s) {
    if (!s.tilt) return std::nullopt;
    FrameChange f = *s.tilt;
    for (double& d : f.decentre) d *= r.millimetresPerUnit;
    return f;
}

LensTableRow lensRow(const ZmxReader& r, const RawSurface& s, int number, const LensTableRow* before, bool reversed) {
    const double u = r.millimetresPerUnit;
    LensTableRow row;
    row.line = s.line;
    row.stop = s.stopLine != 0;
    row.name = s.comment;
    if (!s.thicknessLine) r.fail(s.line, "SURF " + std::to_string(number) + " has no DISZ (thickness to the next surface)");
    row.gap = s.thickness * u;
    if (!std::isfinite(row.gap))
        r.fail(s.thicknessLine, "DISZ must be a finite thickness (INFINITY only on the object surface, SURF 0)");
    if (s.type == "COORDBRK") {
        if (s.stopLine) r.fail(s.stopLine, "a coordinate break cannot be the stop");
        row.coordinateBreak = true;
        row.frame = coordinateBreak(r, s);
        setMedium(row, s, before);
        return row;
    }
    if (s.curvature != 0) row.radius = static_cast<double>(u / s.curvature);
    if (!std::isfinite(row.radius)) r.fail(s.curvatureLine, "CURV is too small: the radius is not a finite number of mm");
    if (row.gap < 0 && !reversed)
        r.fail(s.thicknessLine, "negative thickness " + formatNumber(s.thickness) +
                                    " where the light travels toward the image: a negative DISZ is allowed only after a mirror");
    setMedium(row, s, before);
    row.conic = s.conic;
    row.aspheric = asphericTerms(r, s);
    row.form = surfaceForm(r, s);
    row.frame = surfaceTilt(r, s);
    row.coating = s.coating;
    // The clear aperture is DIAM (Zemax's semi-diameter); a circular aperture overrides it, and the
    // mechanical semi-diameter stands in where DIAM is 0. A rectangle or ellipse (SQAP, ELAP), or
    // any aperture decentred by OBDC, travels as a shape.
    const double semi = s.apertureRadius > 0 ? s.apertureRadius
                        : s.semiDiameter > 0 ? s.semiDiameter
                                             : s.mechanicalSemiDiameter;
    row.diameter = 2 * semi * u;
    row.obscurationDiameter = 2 * s.obscurationRadius * u;
    const bool decentred = s.apertureCentreX != 0 || s.apertureCentreY != 0;
    auto placed = [&](SurfaceAperture a) {
        a.halfWidthX *= u, a.halfWidthY *= u;
        a.centreX = s.apertureCentreX * u, a.centreY = s.apertureCentreY * u;
        return a;
    };
    if (s.clearShape) {
        row.clearShape = placed(*s.clearShape);
    } else if (decentred) {
        SurfaceAperture circle;
        circle.halfWidthX = circle.halfWidthY = semi;
        row.clearShape = placed(circle);
    }
    if (s.obscurationShape) row.obscurationShape = placed(*s.obscurationShape);
    if (row.clearShape) row.diameter = 2 * row.clearShape->reach();
    // DIAM 0 and nothing else: the semi-diameter is left to the program (Zemax's automatic solve
    // recomputes it), as a Code V surface without CIR; lenslab derives it from the aperture and fields.
    row.automaticDiameter = row.diameter == 0 && s.semiDiameterLine && s.semiDiameter == 0 && !s.clearShape;
    if (row.automaticDiameter) return row;
    if (!(row.diameter > 0) || !std::isfinite(row.diameter))
        r.fail(s.line, "SURF " + std::to_string(number) + " has no positive semi-diameter (DIAM, MEMA, CLAP or FLAP)");
    if (row.obscurationDiameter >= row.diameter)
        r.fail(s.line, "SURF " + std::to_string(number) + ": the obscuration covers the whole clear aperture");
    return row;
}

// Zemax lists all 24 wavelength slots: FTYP says how many are used; without it, trailing default
// slots past the primary are taken as unused.
std::vector<Wavelength> usedWavelengths(const ZmxReader& r) {
    std::vector<Wavelength> w = r.wavelengths;
    if (r.fields.wavelengths > 0 && r.fields.wavelengths <= int(w.size())) {
        w.resize(std::max(r.fields.wavelengths, r.primarySlot));
        return w;
    }
    if (int(w.size()) == kWavelengthSlots)
        while (int(w.size()) > std::max(r.primarySlot, 1) && w.back().nanometres == kDefaultSlotNanometres &&
               w.back().weight == 1)
            w.pop_back();
    return w;
}

// XFLN/YFLN/FWGN list all 12 slots; FTYP says how many are fields.
void setFields(const ZmxReader& r, LensTable& t) {
    const Fields& f = r.fields;
    static const FieldType kTypes[] = {FieldType::ObjectAngle, FieldType::ObjectHeight, FieldType::ParaxialImageHeight,
                                       FieldType::RealImageHeight};
    t.fields.type = kTypes[f.type];
    const std::size_t n = f.count >= 0 ? std::size_t(f.count) : std::max(f.x.size(), f.y.size());
    const double u = f.type == 0 ? 1 : r.millimetresPerUnit;
    for (std::size_t i = 0; i < n; ++i) {
        if (i >= f.x.size() && i >= f.y.size()) break;
        t.fields.points.push_back({i < f.x.size() ? f.x[i] * u : 0, i < f.y.size() ? f.y[i] * u : 0,
                                   i < f.weights.size() ? f.weights[i] : 1});
    }
}

void setHeader(const ZmxReader& r, LensTable& t) {
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
        if (const auto problem = wavelengthProblem(w.nanometres)) r.fail(w.line, "WAVM: " + *problem);
        t.wavelengths.push_back(w.nanometres);
        t.wavelengthWeights.push_back(w.weight);
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
    if (r.obna > 0) t.objectNumericalAperture = r.obna;
    setFields(r, t);
}

LensTable assemble(const ZmxReader& r, int lastLine) {
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
    if (image.type == "COORDBRK") r.fail(image.line, "the image surface cannot be a coordinate break");
    // Nothing follows the image, so whether its coordinates return does not matter: it is basic,
    // as Code V states an image's decentre (and as a .zmx written from a .seq reads back).
    t.imageFrame = surfaceTilt(r, image);
    if (t.imageFrame) t.imageFrame->mode = FrameMode::Basic;
    if (object.thicknessLine && std::fabs(object.thickness) < 1e10) t.objectDistance = object.thickness * r.millimetresPerUnit;
    t.warnings.insert(t.warnings.begin(), r.warnings.begin(), r.warnings.end());
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
    ZmxReader r;
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
