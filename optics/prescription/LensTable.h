#pragma once
// The lens table as written in a .dat file, before any geometry is derived from it.
#include <array>
#include <cstddef>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "prescription/SurfaceAperture.h"
#include "prescription/DesignFields.h"
#include "prescription/FrameChange.h"
#include "prescription/Medium.h"
#include "prescription/SurfaceForm.h"

namespace lenslab {

// Column 2 of a lens table is either the gap from the previous surface (the course files, first
// row 0) or the gap to the next surface (pbrt's files, last row 0: distance to the film).
enum class TableLayout { GapBefore, GapAfter };

const char* layoutName(TableLayout layout);                    // "gap-before" / "gap-after"
std::optional<TableLayout> parseLayoutName(const std::string& name);

// The most surfaces a table may have. Real designs have well under 50; a bound keeps every
// per-surface structure (exit-pupil search, traces, the blocking surface's int16 index) small and
// the camera's setup short, and refuses generated or fuzzed tables of thousands of rows at once.
constexpr int kMaxLensSurfaces = 256;

// The description (comment lines) travels with every lens listing: bounded, so one file cannot
// bloat them all.
constexpr std::size_t kMaxCommentBytes = 4096;

// Even-asphere polynomial terms: coefficients of r^2, r^4, ..., r^16 (mm^-1, mm^-3, ..., mm^-15).
constexpr int kAsphericTerms = 8;
using AsphericCoefficients = std::array<double, kAsphericTerms>;

// The Fraunhofer lines the lens designer's colour figures use (nm): F (hydrogen, blue), d (helium,
// yellow; the default wavelength), C (hydrogen, red).
constexpr double kWavelengthF = 486.1327;
constexpr double kWavelengthD = 587.5618;
constexpr double kWavelengthC = 656.2725;

struct LensTableRow {
    double radius = 0;    // mm, 0 = flat; positive: centre of curvature on the film side
    double gap = 0;       // mm, as written (meaning depends on the layout); negative only after a mirror
    double index = 0;     // refractive index on the film side at the d line; 0 means air
    double diameter = 0;  // clear aperture diameter, mm
    int line = 0;         // 1-based line in the source text
    bool stop = false;    // the aperture stop (a table's radius 0, N 0 row; a .zmx STOP)
    // A real prescription's medium on the film side: a catalog glass name, or an Abbe number Vd that
    // makes (index, abbe) a model glass. Neither: the index holds at every wavelength.
    std::string glass;
    std::string glassCatalog;  // the catalog the row names with its glass (Code V's N-BK7_SCHOTT), if any
    double abbe = 0;
    double conic = 0;                  // conic constant k (0 sphere, -1 paraboloid)
    AsphericCoefficients aspheric{};   // even-asphere terms, all 0 for a conic or sphere
    bool mirror = false;               // reflects instead of refracting
    double obscurationDiameter = 0;    // central obscuration (mm); rays inside it are blocked
    SurfaceForm form;                  // odd and Q-type aspheres; EvenAsphere: `aspheric` above
    std::optional<SurfaceAperture> clearShape;        // a clear aperture other than `diameter`'s circle
    std::optional<SurfaceAperture> obscurationShape;  // an obscuration other than a central circle
    std::optional<FrameChange> frame;  // this surface's decentre and tilt
    // A Zemax coordinate break: no surface, only `frame` (Basic) and `gap` (along the new axis).
    bool coordinateBreak = false;
    // The file gives no clear aperture: one is derived from its aperture and fields at build time.
    bool automaticDiameter = false;
    std::string name;                  // the file's label for the surface (Code V SLB, Zemax COMM)
    // The coating as written (prescription/Coating.h); empty: the file says nothing, and
    // buildLensSystem applies the default (a real lens's air-glass surfaces are coated).
    std::string coating;
    bool isStop() const { return stop; }
};

// Something the reader or builder let through that the designer should look at: the lens still
// reads (a moulded glass taken as its base glass, edges overlapping at the stated diameters).
struct LensWarning {
    int line = 0;          // in the prescription; 0: the file as a whole
    std::string message;   // names the surfaces, glasses and heights concerned
};

// A file-level glass substitution (ray-optics' .smx beside a prescription, Code V's private
// catalog): the name as the prescription writes it, and what to use for it.
struct GlassSubstitute {
    std::string name;
    std::string glass, catalog;    // a catalog glass to use instead (catalog may be empty), or
    std::optional<Medium> medium;  // a medium given outright (a constant index, a table of indices)
    std::string source;            // "file.smx", "file.seq:12": where the substitution is stated
};

struct LensTable {
    std::string name;      // file name (or upload name) for messages
    std::vector<std::string> comments;  // header comment lines, '#' stripped
    std::vector<LensTableRow> rows;
    TableLayout layout = TableLayout::GapBefore;
    bool layoutDetected = true;  // false when an explicit override decided it
    std::string format = "table";            // "table" (.dat), "zmx" or "seq" (Code V)
    double primaryWavelength = kWavelengthD; // nm: the file's primary wavelength, else the d line
    std::vector<double> wavelengths;         // nm, as the file lists them (may be empty)
    std::vector<std::string> catalogs;       // glass catalogs the file names (.zmx GCAT), searched first
    std::optional<double> designFNumber;     // .zmx FNUM, .seq FNO
    std::optional<double> entrancePupilDiameter;  // .zmx ENPD, .seq EPD, mm
    std::optional<double> objectNumericalAperture;  // .zmx OBNA, .seq NAO
    std::vector<double> wavelengthWeights;   // parallel to wavelengths (1 where the file gives none)
    DesignFields fields;                     // the file's own field list
    // Distance from the first surface back to the object (the object surface's thickness), mm.
    double objectDistance = std::numeric_limits<double>::infinity();
    std::optional<FrameChange> imageFrame;   // the image surface's own decentre and tilt
    std::vector<GlassSubstitute> substitutes;  // searched before the catalogs
    std::vector<LensWarning> warnings;         // from reading; building adds its own
};

// Every problem with a table: the message names the file, the line and the problem.
class LensTableError : public std::runtime_error {
public:
    LensTableError(const std::string& file, int line, const std::string& problem);
    const std::string& file() const { return file_; }
    int line() const { return line_; }
    const std::string& problem() const { return problem_; }

private:
    std::string file_;
    int line_;
    std::string problem_;
};

// The gap from row `row` to the next surface (or the film), in whichever row the layout keeps it.
double& gapAfter(LensTable& table, int row);
double gapAfter(const LensTable& table, int row);

// Parses a lens table from text. `name` is used in messages. Throws LensTableError.
LensTable parseLensTable(const std::string& text, const std::string& name,
                         std::optional<TableLayout> layout = std::nullopt);

// Whether a file name is a lens prescription lenslab reads (".dat" tables, ".zmx" Zemax files, ".seq"
// Code V files), and its name without that extension ("lenses/dgauss.50mm.dat" -> "dgauss.50mm").
bool isLensFileName(const std::string& name);
std::string lensFileStem(const std::string& name);

// Reads and parses a file. Throws LensTableError (also for unreadable files).
LensTable readLensTable(const std::string& path, std::optional<TableLayout> layout = std::nullopt);

}  // namespace lenslab
