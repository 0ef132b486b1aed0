#pragma once
// The lens as geometry: surfaces at signed z positions (origin at the front vertex, +z toward the
// scene, film at negative z), with the media between them and their clear apertures.
#include <optional>
#include <string>
#include <vector>

#include "prescription/Coating.h"
#include "prescription/LensTable.h"
#include "prescription/Medium.h"

namespace lenslab {

struct Surface {
    double z = 0;               // vertex position, mm (<= 0 for every refracting lens)
    double radius = 0;          // mm, 0 = flat; positive: centre of curvature at z - radius
    double curvature = 0;       // 1 / radius, 0 for flat
    double conic = 0;           // conic constant k: 0 sphere, -1 paraboloid, < -1 hyperboloid
    AsphericCoefficients aspheric{};  // coefficients of r^2 ... r^16 (mm^(1-2i)); all 0 but for aspheres
    double indexAfter = 1;      // refractive index on the film side at the lens's wavelength (air = 1)
    Medium mediumAfter = air(); // what indexAfter is evaluated from
    double apertureRadius = 0;  // clear semi-diameter, mm
    double obscurationRadius = 0;  // central obscuration, mm (0: none)
    bool isStop = false;
    bool mirror = false;        // reflects: the ray turns back, in the medium it came through
    Coating coating;            // as the prescription gives it, else the default (buildLensSystem)
    int line = 0;               // source line in the lens table

    bool isAspheric() const;     // has polynomial terms
    bool isConic() const { return conic != 0; }
    // Curvature at the vertex, which is all the paraxial (first-order) optics sees: c + 2 a_2.
    double vertexCurvature() const { return curvature + 2 * aspheric[0]; }
};

struct LensSystem {
    std::string name;
    std::vector<std::string> comments;
    std::vector<Surface> surfaces;  // in the order light from the scene meets them
    int stopIndex = -1;
    TableLayout layout = TableLayout::GapBefore;
    std::string format = "table";            // the source: "table" or "zmx"
    double wavelength = kWavelengthD;        // nm: every indexAfter is evaluated here
    double primaryWavelength = kWavelengthD; // nm: the prescription's own default
    std::optional<double> designFNumber;     // as the prescription states it (.zmx FNUM)
    std::optional<double> entrancePupilDiameter;

    const Surface& stop() const { return surfaces[stopIndex]; }
    double frontZ() const { return surfaces.front().z; }
    double rearZ() const { return surfaces.back().z; }
    // Index of the medium on the scene side of surface i.
    double indexBefore(int i) const { return i == 0 ? 1.0 : surfaces[i - 1].indexAfter; }
    // Which way light from the scene travels along z just after surface i (i = -1: before the lens):
    // -1 toward the film, +1 back toward the scene between mirrors.
    double zDirectionAfter(int i) const;
    bool isDispersive() const;   // some medium's index changes with the wavelength
    bool hasMirrors() const;
};

// Surface sag at height h (how far the surface lies toward the film from its vertex plane): the even
// asphere c h^2 / (1 + sqrt(1 - (1 + k) c^2 h^2)) + sum a_i h^(2i). NaN beyond where it is defined.
double sag(const Surface& s, double h);

// The largest height at which the sag is defined: 1 / (|c| sqrt(1 + k)) for spheres and prolate
// ellipsoids, infinity for paraboloids, hyperboloids and flat surfaces.
double sagDomainRadius(const Surface& s);

// The same lens with every medium evaluated at `wavelength` nm (360-830).
LensSystem atWavelength(const LensSystem& lens, double wavelength);

// Builds and validates the geometry at the table's primary wavelength. Looks up catalog glasses
// (LensTableRow::glass) and makes model glasses (index and abbe). A surface whose row names no
// coating gets the default: every lens table describes a real lens (the bundled ones are all
// published, manufactured designs), so each refracting surface between air and glass carries a
// quarter wave of MgF2 at 550 nm (kDefaultCoatingText); cemented, air-air (the stop) and mirror
// surfaces stay bare. A row's coating overrides it (coat=none for bare glass). Throws LensTableError naming the
// table's line for: a coating that does not parse or sits on a mirror, no stop or more than one, a diameter larger than the surface's sag allows,
// overlapping surfaces, an unknown glass (naming the catalogs searched), a catalog glass whose nd
// contradicts the table's N.
LensSystem buildLensSystem(const LensTable& table);

// readLensTable + buildLensSystem.
LensSystem loadLensSystem(const std::string& path, std::optional<TableLayout> layout = std::nullopt);

// The same lens with the aperture stop opened or closed to `diameter` (mm).
LensSystem withStopDiameter(const LensSystem& lens, double diameter);

}  // namespace lenslab
