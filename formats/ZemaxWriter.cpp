#include "ZemaxWriter.h"

#include <algorithm>
#include <cmath>

#include "ExactNumberText.h"
#include "LineText.h"
#include "WrittenWavelengths.h"
#include "prescription/GlassCatalog.h"
#include "prescription/Wavelength.h"

namespace lenslab {

namespace {

// Zemax lists 12 field slots; the unused ones hold 0 (FTYP says how many are fields).
constexpr std::size_t kFieldSlots = 12;

[[noreturn]] void refuseForZmx(const LensTable& table, int line, const std::string& what) {
    throw LensTableError(table.name, line, what + ": a .zmx cannot hold it");
}

// What lenslab reads from a .seq that a .zmx, as lenslab reads it, states no other way.
[[noreturn]] void refuseUnwritten(const LensTable& table, int line, const std::string& what) {
    throw LensTableError(table.name, line,
                         what + ": lenslab does not write it to a .zmx (keep the prescription's own file)");
}

// A name written as one word of a GLAS or GCAT line; MIRROR and ___BLANK are GLAS's own words.
const std::string& word(const LensTable& table, int line, const std::string& what, const std::string& name) {
    if (const auto problem = wordTextProblem(name)) refuseForZmx(table, line, what + " with " + *problem);
    if (name == "MIRROR" || name == "___BLANK") refuseForZmx(table, line, what + " '" + name + "' (a GLAS keyword)");
    return name;
}

// Text written after a keyword, which the reader takes trimmed (NAME, NOTE, COMM).
const std::string& lineText(const LensTable& table, int line, const std::string& what, const std::string& text) {
    if (const auto problem = lineTextProblem(text)) refuseForZmx(table, line, what + " with " + *problem);
    if (!text.empty() && (text.front() == ' ' || text.front() == '\t' || text.back() == ' ' || text.back() == '\t'))
        refuseForZmx(table, line, what + " '" + text + "' with spaces at its ends (read back trimmed)");
    return text;
}

// The glass a row's name finds; the catalog as well as the name.
std::string foundGlass(const std::string& glass, const std::vector<std::string>& catalogs) {
    const GlassLookup found = findGlass(glass, catalogs);
    return found.glass ? found.glass->catalog + " " + found.glass->name : "";
}

// GCAT: the file's catalogs, then each row's own, refused where that order would find another glass.
std::vector<std::string> fileCatalogs(const LensTable& table) {
    const std::vector<std::string> catalogs = withRowCatalogsInTheFile(table).catalogs;
    for (const LensTableRow& row : table.rows) {
        if (row.glass.empty() || catalogs == table.catalogs) continue;
        std::vector<std::string> own = table.catalogs;
        if (!row.glassCatalog.empty()) own.insert(own.begin(), row.glassCatalog);
        const std::string meant = foundGlass(row.glass, own), read = foundGlass(row.glass, catalogs);
        if (meant != read)
            refuseForZmx(table, row.line, "glass '" + row.glass + "' of catalog " + row.glassCatalog + " (" + meant +
                                        "), which the file's catalog list (GCAT) would make " + read);
    }
    return catalogs;
}

// GLAS name solve pickup nd Vd: a catalog glass by name (nd as the table has it, 0: the catalog's),
// anything else a model glass (___BLANK, solve 1), air (index 0) no line at all.
std::string glassLine(const LensTable& table, const LensTableRow& row) {
    if (row.mirror) return "  GLAS MIRROR\n";
    if (!row.glass.empty()) {
        if (row.abbe != 0) refuseForZmx(table, row.line, "glass '" + row.glass + "' with an Abbe number besides (a catalog glass has its own)");
        return "  GLAS " + word(table, row.line, "a glass name", row.glass) + " 0 0 " + exactNumberText(row.index) + " 0\n";
    }
    if (row.index == 0 && row.abbe == 0) return "";
    if (!(row.index >= 1) || !(row.abbe >= 0))
        refuseForZmx(table, row.line, "a model glass of nd " + exactNumberText(row.index) + ", Vd " + exactNumberText(row.abbe) +
                                    " (GLAS ___BLANK needs nd >= 1 and Vd >= 0)");
    return "  GLAS ___BLANK 1 0 " + exactNumberText(row.index) + " " + exactNumberText(row.abbe) + "\n";
}

std::string parmLine(int index, double value) {
    return "  PARM " + std::to_string(index) + " " + exactNumberText(value) + "\n";
}

// TYPE and its PARM/XDAT lines: even-asphere PARM i multiplies r^(2i); odd-asphere PARM i r^i;
// toroidal PARM 1 the radius of rotation, PARM i the y^(2i - 2) terms; a Q-type XDAT 1 its kind
// (0 Qcon, 1 Qbfs), 2 the term count, 3 the normalisation radius, 4.. the terms.
std::string formLines(const LensTable& table, const LensTableRow& row) {
    const SurfaceForm& f = row.form;
    const bool aspheric = row.aspheric != AsphericCoefficients{};
    if (f.isEvenAsphere()) {
        if (!aspheric) return "  TYPE STANDARD\n";
        std::string out = "  TYPE EVENASPH\n";
        for (int i = 0; i < kAsphericTerms; ++i) out += parmLine(i + 1, row.aspheric[i]);
        return out;
    }
    if (aspheric) refuseForZmx(table, row.line, std::string("even-asphere terms on a surface of the kind ") + surfaceKindName(f.kind));
    std::string out;
    switch (f.kind) {
        case SurfaceKind::OddAsphere:
        case SurfaceKind::Toroidal:
            out = f.kind == SurfaceKind::OddAsphere ? "  TYPE ODDASPH\n" : "  TYPE TOROIDAL\n";
            for (int i = 0; i < f.termCount; ++i) out += parmLine(i + 1, f.terms[i]);
            return out;
        case SurfaceKind::Qbfs:
        case SurfaceKind::Qcon:
            out = "  TYPE QTYPE\n  XDAT 1 " + std::string(f.kind == SurfaceKind::Qbfs ? "1" : "0") + "\n  XDAT 2 " +
                  std::to_string(f.termCount) + "\n  XDAT 3 " + exactNumberText(f.normalisationRadius) + "\n";
            for (int m = 0; m < f.termCount; ++m) out += "  XDAT " + std::to_string(m + 4) + " " + exactNumberText(f.terms[m]) + "\n";
            return out;
        case SurfaceKind::EvenAsphere: break;
    }
    return out;
}

// SCBD 1 order 0 dx dy tiltx tilty tiltz: a surface's own decentre and tilt, the coordinates
// returning after it (lenslab reads it as Code V's DAR; on the image, where nothing follows, as basic).
std::string decentreLine(const LensTable& table, int line, const FrameChange& f) {
    if (f.decentre[2] != 0) refuseUnwritten(table, line, "a decentre along z (Code V's ZDE)");
    return "  SCBD 1 " + std::string(f.order == TiltOrder::TiltThenDecentre ? "1" : "0") + " 0 " +
           exactNumberText(f.decentre[0]) + " " + exactNumberText(f.decentre[1]) + " " + exactNumberText(f.tiltDegrees[0]) +
           " " + exactNumberText(f.tiltDegrees[1]) + " " + exactNumberText(f.tiltDegrees[2]) + "\n";
}

// SQAP/ELAP (clear) and SQOB/ELOB (obscuration) half widths with one decentre (OBDC) for both; a
// decentred circle is DIAM with OBDC.
std::string apertureLines(const LensTable& table, const LensTableRow& row) {
    std::string out;
    const auto shapeLine = [&](const SurfaceAperture& a, const char* rectangle, const char* ellipse) {
        return std::string("  ") + (a.kind == ApertureKind::Rectangular ? rectangle : ellipse) + " " +
               exactNumberText(a.halfWidthX) + " " + exactNumberText(a.halfWidthY) + " 0\n";
    };
    if (row.clearShape && row.clearShape->kind != ApertureKind::Circular) out += shapeLine(*row.clearShape, "SQAP", "ELAP");
    if (row.obscurationShape) {
        if (row.obscurationShape->kind == ApertureKind::Circular)
            refuseForZmx(table, row.line, "a decentred circular obscuration (OBSC is about the vertex)");
        out += shapeLine(*row.obscurationShape, "SQOB", "ELOB");
    }
    const SurfaceAperture* clear = row.clearShape ? &*row.clearShape : nullptr;
    const SurfaceAperture* obscuration = row.obscurationShape ? &*row.obscurationShape : nullptr;
    const SurfaceAperture* placed = clear ? clear : obscuration;
    if (!placed) return out;
    const auto centred = [](const SurfaceAperture* a) { return !a || (a->centreX == 0 && a->centreY == 0); };
    if (!clear && !centred(obscuration))
        refuseForZmx(table, row.line, "a decentred obscuration on a circular clear aperture about the vertex (OBDC moves both)");
    if (clear && obscuration && (clear->centreX != obscuration->centreX || clear->centreY != obscuration->centreY))
        refuseForZmx(table, row.line, "a clear aperture and an obscuration decentred differently (OBDC moves both)");
    if (clear && clear->kind == ApertureKind::Circular && centred(clear))
        refuseForZmx(table, row.line, "a circular clear aperture about the vertex given as a shape");
    if (!centred(placed)) out += "  OBDC " + exactNumberText(placed->centreX) + " " + exactNumberText(placed->centreY) + "\n";
    return out;
}

// DIAM: the semi-diameter; with a shaped clear aperture the reader takes the shape's reach, and a
// decentred circle's radius from DIAM. An automatic one is DIAM 0 (Zemax's automatic solve
// recomputes it; lenslab derives it from the aperture and fields).
double semiDiameter(const LensTable& table, const LensTableRow& row) {
    if (row.automaticDiameter) {
        if (row.diameter != 0 || row.clearShape) refuseForZmx(table, row.line, "an automatic clear aperture with a diameter or shape");
        return 0;
    }
    if (!row.clearShape) return row.diameter / 2;
    return row.clearShape->kind == ApertureKind::Circular ? row.clearShape->halfWidthX : row.clearShape->reach();
}

// TYPE COORDBRK: PARM 1, 2 decentre x, y; 3, 4, 5 tilt about x, y, z; 6 the order flag.
std::string coordinateBreakLines(const FrameChange& f, double gap) {
    std::string out = "  TYPE COORDBRK\n  CURV 0\n  DISZ " + exactNumberText(gap) + "\n";
    for (int i = 0; i < 2; ++i) out += parmLine(i + 1, f.decentre[i]);
    for (int i = 0; i < 3; ++i) out += parmLine(i + 3, f.tiltDegrees[i]);
    return out + parmLine(6, f.order == TiltOrder::TiltThenDecentre ? 1 : 0);
}

// The inverse motion of a frame change as a coordinate break: the tilts undone in the other order,
// then the decentre (FrameChange.h: flag 1 is flag 0's inverse with the values negated).
FrameChange inverted(const FrameChange& f) {
    FrameChange back = f;
    for (double& d : back.decentre) d = -d;
    for (double& t : back.tiltDegrees) t = -t;
    back.order = f.order == TiltOrder::DecentreThenTilt ? TiltOrder::TiltThenDecentre : TiltOrder::DecentreThenTilt;
    return back;
}

// A surface's Code V decentre whose coordinates do not return after it, as Zemax states it:
// coordinate breaks around the surface. Basic: a break into the moved frame before it. BEN: that,
// and after the surface (DISZ 0) the tilt once more about its vertex. REV: after the surface the
// inverse motion. The gap moves to the break after the surface. Read back, the table has these
// breaks as rows of their own: the same lens, not the same rows (docs/prescriptions.md).
struct Breaks {
    std::optional<FrameChange> before, after;
};
Breaks breaksAround(const LensTable& table, const LensTableRow& row) {
    if (!row.frame || row.frame->isIdentity() || row.frame->mode == FrameMode::DecentreAndReturn) return {};
    const FrameChange& f = *row.frame;
    if (f.decentre[2] != 0) refuseUnwritten(table, row.line, "a decentre along z (Code V's ZDE)");
    switch (f.mode) {
        case FrameMode::Basic: return {f, std::nullopt};
        case FrameMode::Bend: {
            FrameChange tilt = f;
            tilt.decentre = {};
            return {f, tilt};
        }
        case FrameMode::Reverse: return {std::nullopt, inverted(f)};
        case FrameMode::DecentreAndReturn: break;
    }
    return {};
}

std::string surfaceBlocks(const LensTable& table, const LensTableRow& row, int& number) {
    const auto surf = [&] { return "SURF " + std::to_string(number++) + "\n"; };
    const std::string name = row.name.empty() ? "" : "  COMM " + lineText(table, row.line, "a surface name", row.name) + "\n";
    if (row.coordinateBreak) {
        const FrameChange f = row.frame.value_or(FrameChange{});
        if (f.mode != FrameMode::Basic) refuseForZmx(table, row.line, "a coordinate break whose coordinates return or bend");
        if (f.decentre[2] != 0) refuseForZmx(table, row.line, "a coordinate break decentred along z (its DISZ is the move)");
        return surf() + name + coordinateBreakLines(f, row.gap);
    }
    const Breaks breaks = breaksAround(table, row);
    std::string out = breaks.before ? surf() + coordinateBreakLines(*breaks.before, 0) : "";
    out += surf() + name + formLines(table, row);
    out += "  CURV " + (row.radius == 0 ? std::string("0") : exactReciprocalText(row.radius)) + "\n";
    out += "  DISZ " + exactNumberText(breaks.after ? 0.0 : row.gap) + "\n";
    out += glassLine(table, row);
    if (row.conic != 0) out += "  CONI " + exactNumberText(row.conic) + "\n";
    out += "  DIAM " + exactNumberText(semiDiameter(table, row)) + "\n";
    if (row.obscurationDiameter > 0) out += "  OBSC 0 " + exactNumberText(row.obscurationDiameter / 2) + "\n";
    out += apertureLines(table, row);
    if (row.frame && !row.frame->isIdentity() && !breaks.before && !breaks.after) out += decentreLine(table, row.line, *row.frame);
    if (row.stop) out += "  STOP\n";
    if (!row.coating.empty()) out += "  COAT " + row.coating + "\n";
    if (breaks.after) out += surf() + coordinateBreakLines(*breaks.after, row.gap);
    return out;
}

std::string noteLines(const LensTable& table) {
    std::string out;
    for (std::size_t i = 0; i < table.comments.size(); ++i) {
        const std::string& text = lineText(table, 0, "comment " + std::to_string(i + 1), table.comments[i]);
        if (text.empty()) refuseForZmx(table, 0, "comment " + std::to_string(i + 1) + ", an empty line (read back as none)");
        out += (i == 0 ? "NAME " : "NOTE 0 ") + text + "\n";
    }
    return out;
}

// WAVM slot micrometres weight, and PWAV naming the primary unless it is the d line a file without
// WAVM lines is read at.
std::string wavelengthLines(const LensTable& table, const std::vector<double>& nm) {
    std::string out;
    for (std::size_t i = 0; i < nm.size(); ++i) {
        if (const auto problem = wavelengthProblem(nm[i])) refuseForZmx(table, 0, "the " + *problem);
        const double weight = i < table.wavelengthWeights.size() ? table.wavelengthWeights[i] : 1;
        out += "WAVM " + std::to_string(i + 1) + " " + exactThousandthText(nm[i]) + " " + exactNumberText(weight) + "\n";
    }
    if (!nm.empty())
        out += "PWAV " + std::to_string(std::find(nm.begin(), nm.end(), table.primaryWavelength) - nm.begin() + 1) + "\n";
    return out;
}

// FTYP type 0 fields wavelengths 0 0 0, then XFLN, YFLN, FWGN over Zemax's 12 slots (more when
// the table has more fields). FTYP's wavelength count keeps a list of 24 whose last ones are
// Zemax's unused-slot default (0.55 um, weight 1) from being read as unused.
std::string fieldLines(const DesignFields& fields, std::size_t wavelengths) {
    if (fields.points.empty() && fields.type == FieldType::ObjectAngle && wavelengths == 0) return "";
    std::string out = "FTYP " + std::to_string(int(fields.type)) + " 0 " + std::to_string(fields.points.size()) + " " +
                      std::to_string(wavelengths) + " 0 0 0\n";
    const std::size_t slots = std::max(kFieldSlots, fields.points.size());
    const auto slotLine = [&](const char* keyword, double FieldPoint::*value, double unused) {
        std::string line = keyword;
        for (std::size_t i = 0; i < slots; ++i)
            line += " " + exactNumberText(i < fields.points.size() ? fields.points[i].*value : unused);
        return line + "\n";
    };
    return out + slotLine("XFLN", &FieldPoint::x, 0) + slotLine("YFLN", &FieldPoint::y, 0) +
           slotLine("FWGN", &FieldPoint::weight, 1);
}

// SURF 0: the object, at its distance (INFINITY when the table has none).
std::string objectBlock(const LensTable& table) {
    std::string out = "SURF 0\n  TYPE STANDARD\n  CURV 0\n  DISZ ";
    if (!std::isfinite(table.objectDistance)) return out + "INFINITY\n";
    if (std::fabs(table.objectDistance) >= 1e10)
        refuseForZmx(table, 0, "an object distance of 1e10 mm or more (read as infinite)");
    return out + exactNumberText(table.objectDistance) + "\n";
}

}  // namespace

LensTable withRowCatalogsInTheFile(LensTable table) {
    for (LensTableRow& row : table.rows) {
        if (!row.glassCatalog.empty() &&
            std::find(table.catalogs.begin(), table.catalogs.end(), row.glassCatalog) == table.catalogs.end())
            table.catalogs.push_back(row.glassCatalog);
        row.glassCatalog.clear();
    }
    return table;
}

std::string writeZemaxText(const LensTable& table) {
    if (table.layout != TableLayout::GapAfter)
        throw LensTableError(table.name, 0, "a .zmx needs gap-after rows (DISZ is the thickness to the next surface)");
    if (!table.substitutes.empty())
        refuseUnwritten(table, 0, "glasses substituted by " + table.substitutes.front().source);
    std::string out = "VERS 190513 0 0\nMODE SEQ\n" + noteLines(table) + "UNIT MM X W X CM MR CPMM\n";
    if (table.entrancePupilDiameter) out += "ENPD " + exactNumberText(*table.entrancePupilDiameter) + "\n";
    if (table.designFNumber) out += "FNUM " + exactNumberText(*table.designFNumber) + " 0\n";
    if (table.objectNumericalAperture) out += "OBNA " + exactNumberText(*table.objectNumericalAperture) + " 0\n";
    const std::vector<std::string> catalogs = fileCatalogs(table);
    if (!catalogs.empty()) {
        out += "GCAT";
        for (const std::string& c : catalogs) out += " " + word(table, 0, "a catalog name", c);
        out += "\n";
    }
    const std::vector<double> nm = writtenWavelengths(table);
    out += fieldLines(table.fields, nm.size());
    out += wavelengthLines(table, nm);
    out += objectBlock(table);
    int number = 1;
    for (const LensTableRow& row : table.rows) out += surfaceBlocks(table, row, number);
    out += "SURF " + std::to_string(number) + "\n  TYPE STANDARD\n  CURV 0\n  DISZ 0\n";
    if (table.imageFrame && !table.imageFrame->isIdentity()) {
        if (table.imageFrame->mode != FrameMode::Basic) refuseForZmx(table, 0, "an image surface decentre that returns, bends or reverses");
        out += decentreLine(table, 0, *table.imageFrame);
    }
    return out;
}

}  // namespace lenslab
