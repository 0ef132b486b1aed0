#include "CodeVWriter.h"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "ExactNumberText.h"
#include "LineText.h"
#include "WrittenWavelengths.h"
#include "prescription/GlassCatalog.h"
#include "prescription/RowMedium.h"
#include "prescription/Wavelength.h"

namespace lenslab {

namespace {

// What one command of lenslab's Code V reader takes: 24 wavelengths (WL), 100 fields (XAN ...).
constexpr std::size_t kMaxWavelengths = 24;
constexpr std::size_t kMaxFields = 100;

// Code V writes an object at infinity as a thickness of 1e10; the reader takes 1e10 and more so.
constexpr double kInfiniteObject = 1e10;

[[noreturn]] void refuseForSeq(const LensTable& table, int line, const std::string& what) {
    throw LensTableError(table.name, line, what + ": a .seq, as lenslab reads it, cannot hold it");
}

// TIT and SLB text as one quoted word: the reader takes it whole between quotes of either kind, so
// it may hold the other kind but not both, and no line break.
std::string quoted(const LensTable& table, int line, const std::string& what, const std::string& text) {
    if (const auto problem = lineTextProblem(text)) refuseForSeq(table, line, what + " with " + *problem);
    const bool single = text.find('\'') != std::string::npos;
    if (single && text.find('"') != std::string::npos)
        refuseForSeq(table, line, what + " '" + text + "' with both kinds of quote in it");
    const char quote = single ? '"' : '\'';
    return quote + text + quote;
}

// A glass or catalog name as one plain word of S that the reader takes for a name: not its own
// words (REFL, AIR), not a fictitious glass (',' or ':' between nd and Vd, a glass code's digits),
// nothing that splits (';'), ends ('!', a trailing '&') or quotes the command.
const std::string& glassWord(const LensTable& table, int line, const std::string& what, const std::string& name) {
    if (const auto problem = wordTextProblem(name)) refuseForSeq(table, line, what + " with " + *problem);
    std::string upper = name;
    for (char& c : upper) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    if (upper == "REFL" || upper == "AIR" || name.find_first_of(",:;!&'\"") != std::string::npos ||
        name.find_first_not_of("0123456789.") == std::string::npos)
        refuseForSeq(table, line, what + " '" + name + "', which a .seq reads as something else than a glass name");
    return name;
}

// The medium words of S: REFL for a mirror, a catalog glass as NAME_CATALOG (Code V's form: the
// reader splits at the last underscore) or its bare name, a model glass as nd:Vd, air nothing.
std::string mediumWords(const LensTable& table, const LensTableRow& row) {
    if (row.mirror) return " REFL";
    if (!row.glass.empty()) {
        const std::string& name = glassWord(table, row.line, "a glass name", row.glass);
        if (row.glassCatalog.empty()) {
            if (name.find('_') != std::string::npos)
                refuseForSeq(table, row.line, "glass '" + name + "' with no catalog, whose underscore reads as NAME_CATALOG");
            return " " + name;
        }
        const std::string& catalog = glassWord(table, row.line, "a catalog name", row.glassCatalog);
        if (catalog.find('_') != std::string::npos)
            refuseForSeq(table, row.line, "catalog '" + catalog + "' with an underscore (NAME_CATALOG splits at the last one)");
        return " " + name + "_" + catalog;
    }
    if (row.index == 0 && row.abbe == 0) return "";
    if (row.abbe == 0)
        refuseForSeq(table, row.line, "a medium of plain index " + exactNumberText(row.index) +
                                          " with no Abbe number (a .seq's glass is a catalog name or nd:Vd, a model glass with dispersion)");
    if (!(row.index > 1 && row.abbe > 0))
        refuseForSeq(table, row.line, "a model glass of nd " + exactNumberText(row.index) + ", Vd " + exactNumberText(row.abbe) +
                                          " (nd:Vd needs nd > 1 and Vd > 0)");
    return " " + exactNumberText(row.index) + ":" + exactNumberText(row.abbe);
}

// CON (a conic) or ASP (an even asphere) with K, the conic constant, and A .. G, the terms of r^4 ..
// r^16; a sphere needs none of them.
std::string codeVFormLines(const LensTable& table, const LensTableRow& row) {
    if (!row.form.isEvenAsphere())
        refuseForSeq(table, row.line, std::string("a surface of the kind ") + surfaceKindName(row.form.kind) +
                                          " (lenslab reads Code V's spheres, conics and even aspheres)");
    if (row.aspheric[0] != 0) refuseForSeq(table, row.line, "an r^2 aspheric term (Code V's A is the r^4 term)");
    const bool aspheric = std::any_of(row.aspheric.begin() + 1, row.aspheric.end(), [](double a) { return a != 0; });
    if (!aspheric && row.conic == 0) return "";
    std::string out = aspheric ? "  ASP\n" : "  CON\n";
    if (row.conic != 0) out += "  K " + exactNumberText(row.conic) + "\n";
    for (int i = 1; i < kAsphericTerms; ++i)
        if (row.aspheric[i] != 0) out += "  " + std::string(1, "ABCDEFG"[i - 1]) + " " + exactNumberText(row.aspheric[i]) + "\n";
    return out;
}

bool centred(const SurfaceAperture& a) { return a.centreX == 0 && a.centreY == 0; }

// CIR (the radius), REX/REY or ELX/ELY (half widths), then ADX/ADY for its decentre; `qualifier` OBS
// makes it an obscuration.
std::string shapeLines(const LensTable& table, int line, const SurfaceAperture& a, const std::string& qualifier) {
    if (!(a.halfWidthX > 0 && a.halfWidthY > 0))
        refuseForSeq(table, line, "an aperture of half widths " + exactNumberText(a.halfWidthX) + " and " + exactNumberText(a.halfWidthY) +
                                      " (each needs a positive semi-aperture)");
    const auto command = [&](const char* name, double value) { return "  " + std::string(name) + qualifier + " " + exactNumberText(value) + "\n"; };
    std::string out;
    switch (a.kind) {
        case ApertureKind::Circular:
            if (a.halfWidthX != a.halfWidthY) refuseForSeq(table, line, "a circular aperture of two radii");
            out = command("CIR", a.halfWidthX);
            break;
        case ApertureKind::Rectangular: out = command("REX", a.halfWidthX) + command("REY", a.halfWidthY); break;
        case ApertureKind::Elliptical: out = command("ELX", a.halfWidthX) + command("ELY", a.halfWidthY); break;
    }
    if (a.centreX != 0) out += "  ADX " + exactNumberText(a.centreX) + "\n";
    if (a.centreY != 0) out += "  ADY " + exactNumberText(a.centreY) + "\n";
    return out;
}

// The clear aperture (none: left to the program, which lenslab derives from the aperture and
// fields) and the obscuration. A circle about the vertex is the table's diameter, any other shape
// the table's shape, as the reader makes them.
std::string codeVApertureLines(const LensTable& table, const LensTableRow& row) {
    std::string out;
    if (row.automaticDiameter) {
        if (row.diameter != 0 || row.clearShape) refuseForSeq(table, row.line, "an automatic clear aperture with a diameter or shape");
    } else if (row.clearShape) {
        if (row.clearShape->kind == ApertureKind::Circular && centred(*row.clearShape))
            refuseForSeq(table, row.line, "a circular clear aperture about the vertex given as a shape (CIR is the diameter)");
        out += shapeLines(table, row.line, *row.clearShape, "");
    } else {
        if (!(row.diameter > 0))
            refuseForSeq(table, row.line, "a clear aperture of diameter " + exactNumberText(row.diameter) +
                                              " (CIR needs a positive semi-aperture; no CIR is an automatic one)");
        out += "  CIR " + exactNumberText(row.diameter / 2) + "\n";
    }
    if (row.obscurationDiameter > 0 && row.obscurationShape)
        refuseForSeq(table, row.line, "a central obscuration and a shaped one (a surface has one obscuration)");
    if (row.obscurationDiameter > 0) out += "  CIR OBS " + exactNumberText(row.obscurationDiameter / 2) + "\n";
    if (row.obscurationShape) {
        if (row.obscurationShape->kind == ApertureKind::Circular && centred(*row.obscurationShape))
            refuseForSeq(table, row.line, "a central circular obscuration given as a shape (CIR OBS is the obscuration diameter)");
        out += shapeLines(table, row.line, *row.obscurationShape, " OBS");
    }
    return out;
}

// XDE YDE ZDE (mm), ADE BDE CDE (degrees) in Code V's order: decentre, then tilt about x, the new y
// and the newest z. DAR, BEN or REV say what follows the surface (none: basic); a basic frame of
// zeros is XDE 0, so that the frame is there to read back.
std::string frameLines(const LensTable& table, int line, const FrameChange& f) {
    if (f.order == TiltOrder::TiltThenDecentre)
        refuseForSeq(table, line, "a tilt before the decentre (Zemax's order flag 1; Code V decentres, then tilts)");
    static const char* const kDecentres[] = {"XDE", "YDE", "ZDE"};
    static const char* const kTilts[] = {"ADE", "BDE", "CDE"};
    std::string out;
    for (int i = 0; i < 3; ++i)
        if (f.decentre[i] != 0) out += "  " + std::string(kDecentres[i]) + " " + exactNumberText(f.decentre[i]) + "\n";
    for (int i = 0; i < 3; ++i)
        if (f.tiltDegrees[i] != 0) out += "  " + std::string(kTilts[i]) + " " + exactNumberText(f.tiltDegrees[i]) + "\n";
    switch (f.mode) {
        case FrameMode::DecentreAndReturn: out += "  DAR\n"; break;
        case FrameMode::Bend: out += "  BEN\n"; break;
        case FrameMode::Reverse: out += "  REV\n"; break;
        case FrameMode::Basic: break;
    }
    return out.empty() ? "  XDE 0\n" : out;
}

// S radius thickness medium (RDM: a radius, 0 flat), then what the surface carries: STO, SLB, its
// form, apertures and decentre.
std::string surfaceLines(const LensTable& table, const LensTableRow& row) {
    if (row.coordinateBreak)
        refuseForSeq(table, row.line, "a coordinate break other than the decentre of the surface after it (no thickness, basic, "
                                      "no name, before a surface without a decentre of its own)");
    if (!row.coating.empty()) refuseForSeq(table, row.line, "the coating '" + row.coating + "' (lenslab reads no coating from a .seq)");
    std::string out = "S " + exactNumberText(row.radius) + " " + exactNumberText(row.gap) + mediumWords(table, row) + "\n";
    if (row.stop) out += "  STO\n";
    if (!row.name.empty()) out += "  SLB " + quoted(table, row.line, "a surface name", row.name) + "\n";
    out += codeVFormLines(table, row) + codeVApertureLines(table, row);
    if (row.frame) out += frameLines(table, row.line, *row.frame);
    return out;
}

// The title and notes, each a TIT line (lenslab reads every TIT as one comment, the first the title).
std::string titleLines(const LensTable& table) {
    std::string out;
    for (std::size_t i = 0; i < table.comments.size(); ++i) {
        const std::string what = "comment " + std::to_string(i + 1);
        if (table.comments[i].empty()) refuseForSeq(table, 0, what + ", an empty line (read back as none)");
        out += "TIT " + quoted(table, 0, what, table.comments[i]) + "\n";
    }
    return out;
}

// WL (nm), REF (the primary's place in that list), WTW (the weights; 1 where the table has none).
std::string wavelengthLines(const LensTable& table) {
    const std::vector<double> nm = writtenWavelengths(table);
    if (nm.empty()) return "";
    if (nm.size() > kMaxWavelengths) refuseForSeq(table, 0, std::to_string(nm.size()) + " wavelengths (WL lists 24 at most)");
    std::string wl = "WL", weights = "WTW";
    for (std::size_t i = 0; i < nm.size(); ++i) {
        if (const auto problem = wavelengthProblem(nm[i])) refuseForSeq(table, 0, "the " + *problem);
        wl += " " + exactNumberText(nm[i]);
        weights += " " + exactNumberText(i < table.wavelengthWeights.size() ? table.wavelengthWeights[i] : 1);
    }
    const auto primary = std::find(nm.begin(), nm.end(), table.primaryWavelength) - nm.begin();
    return wl + "\nREF " + std::to_string(primary + 1) + "\n" + weights + "\n";
}

// The fields by their type's commands: XAN/YAN object angles (degrees), XOB/YOB object heights,
// XIM/YIM paraxial and XRI/YRI real image heights (mm); WTF their weights.
std::string fieldLines(const LensTable& table) {
    const DesignFields& fields = table.fields;
    if (fields.points.empty()) {
        if (fields.type != FieldType::ObjectAngle)
            refuseForSeq(table, 0, std::string("a field type (") + fieldTypeName(fields.type) + ") without fields (a .seq states it by its fields)");
        return "";
    }
    if (fields.points.size() > kMaxFields) refuseForSeq(table, 0, std::to_string(fields.points.size()) + " fields (100 at most)");
    static const char* const kTypeLetters[] = {"AN", "OB", "IM", "RI"};
    const std::string letters = kTypeLetters[int(fields.type)];
    std::string x = "X" + letters, y = "Y" + letters, weights = "WTF";
    for (const FieldPoint& p : fields.points) {
        x += " " + exactNumberText(p.x);
        y += " " + exactNumberText(p.y);
        weights += " " + exactNumberText(p.weight);
    }
    return x + "\n" + y + "\n" + weights + "\n";
}

// EPD (mm), FNO, NAO: the aperture the design states, as the reader checks them.
std::string apertureSpecLines(const LensTable& table) {
    std::string out;
    if (const auto& epd = table.entrancePupilDiameter) {
        if (!(*epd > 0)) refuseForSeq(table, 0, "an entrance pupil diameter of " + exactNumberText(*epd));
        out += "EPD " + exactNumberText(*epd) + "\n";
    }
    if (const auto& fno = table.designFNumber) {
        if (!(*fno > 0)) refuseForSeq(table, 0, "an f-number of " + exactNumberText(*fno));
        out += "FNO " + exactNumberText(*fno) + "\n";
    }
    if (const auto& nao = table.objectNumericalAperture) {
        if (!(*nao > 0 && *nao < 1)) refuseForSeq(table, 0, "an object numerical aperture of " + exactNumberText(*nao));
        out += "NAO " + exactNumberText(*nao) + "\n";
    }
    return out;
}

// SO: the object surface, flat, its thickness the object distance (1e10 for one at infinity).
std::string objectLine(const LensTable& table) {
    if (!std::isfinite(table.objectDistance)) return "SO 0 1e10\n";
    if (std::fabs(table.objectDistance) >= kInfiniteObject)
        refuseForSeq(table, 0, "an object distance of 1e10 mm or more (read as infinite)");
    return "SO 0 " + exactNumberText(table.objectDistance) + "\n";
}

// SI: the film, flat and of no thickness of its own (the last row's gap reaches it); its decentre
// and tilt basic, as nothing follows it.
std::string imageLines(const LensTable& table) {
    std::string out = "SI 0 0\n";
    if (table.imageFrame) {
        if (table.imageFrame->mode != FrameMode::Basic)
            refuseForSeq(table, 0, "an image surface decentre that returns, bends or reverses (nothing follows the image)");
        out += frameLines(table, 0, *table.imageFrame);
    }
    return out;
}

// The catalog the table's catalogs find a glass in (its base glass's for a moulded variant, as the
// lens is built); empty when none has it.
std::string catalogFound(const std::string& glass, const std::vector<std::string>& catalogs) {
    GlassLookup found = findGlass(glass, catalogs);
    const std::string base = mouldedBaseName(glass);
    if (!found.glass && !base.empty()) found = findGlass(base, catalogs);
    return found.glass ? found.glass->catalog : "";
}

// A coordinate break of no thickness that moves nothing.
bool movesNothing(const LensTableRow& row) {
    return row.coordinateBreak && row.gap == 0 && !row.stop && row.name.empty() &&
           (!row.frame || (row.frame->mode == FrameMode::Basic && row.frame->isIdentity()));
}

// A coordinate break of no thickness that moves only the surface after it, at that surface's own
// vertex: that surface's basic decentre, decentring and then tilting as Code V does.
bool isTheNextSurfacesDecentre(const LensTableRow& row, const LensTableRow& next) {
    return row.coordinateBreak && row.gap == 0 && !row.stop && row.name.empty() && !next.coordinateBreak && !next.frame &&
           row.frame && row.frame->mode == FrameMode::Basic && row.frame->order == TiltOrder::DecentreThenTilt;
}

}  // namespace

LensTable asCodeVStatesIt(LensTable table) {
    auto& rows = table.rows;
    for (std::size_t i = 0; i < rows.size();) {
        if (movesNothing(rows[i])) {
            rows.erase(rows.begin() + std::ptrdiff_t(i));
        } else if (i + 1 < rows.size() && isTheNextSurfacesDecentre(rows[i], rows[i + 1])) {
            rows[i + 1].frame = rows[i].frame;
            rows.erase(rows.begin() + std::ptrdiff_t(i));
        } else {
            ++i;
        }
    }
    for (std::size_t i = 0; i < rows.size(); ++i) {
        LensTableRow& row = rows[i];
        if (!row.glass.empty()) {
            if (row.glassCatalog.empty() && !table.catalogs.empty()) row.glassCatalog = catalogFound(row.glass, table.catalogs);
            row.index = row.abbe = 0;
        } else if (row.index == 1 && row.abbe == 0) {
            row.index = 0;
        }
        if (row.mirror) {
            const LensTableRow arrivedIn = i > 0 ? rows[i - 1] : LensTableRow{};
            row.index = arrivedIn.index, row.abbe = arrivedIn.abbe;
            row.glass = arrivedIn.glass, row.glassCatalog = arrivedIn.glassCatalog;
        }
    }
    table.catalogs.clear();
    return table;
}

std::string writeCodeVText(const LensTable& original) {
    if (original.layout != TableLayout::GapAfter)
        throw LensTableError(original.name, 0, "a .seq needs gap-after rows (S's thickness is the gap to the next surface)");
    if (!original.substitutes.empty())
        throw LensTableError(original.name, 0, "glasses substituted by " + original.substitutes.front().source +
                                                   ": lenslab does not write them into a .seq (the .smx beside it holds them)");
    const LensTable table = asCodeVStatesIt(original);
    const auto stop = [](const LensTableRow& row) { return row.stop; };
    const auto first = std::find_if(table.rows.begin(), table.rows.end(), stop);
    if (first == table.rows.end())
        refuseForSeq(table, 0, "a lens without a stop (a .seq's first surface is the stop when none is marked STO)");
    if (const auto second = std::find_if(first + 1, table.rows.end(), stop); second != table.rows.end())
        refuseForSeq(table, second->line, "a second stop");
    std::string out = "RDM\nLEN\n" + titleLines(table) + "DIM M\n" + wavelengthLines(table) + fieldLines(table) +
                      apertureSpecLines(table) + objectLine(table);
    for (const LensTableRow& row : table.rows) out += surfaceLines(table, row);
    return out + imageLines(table) + "GO\n";
}

}  // namespace lenslab
