#pragma once
// The lens as geometry: surfaces at signed z positions (origin at the front vertex, +z toward the
// scene, film at negative z), with the media between them and their clear apertures. A decentred or
// tilted surface carries the rigid motions of coordinates into its own frame and on to the next
// surface's; each surface's z is measured along the axis of the coordinates it is placed in, so a
// system folded by mirrors reads like the same system unfolded (docs/prescriptions.md).
#include <limits>
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
    // The file gave no clear aperture: apertureRadius is the paraxial beam's (for drawing and for
    // the first-order searches) and the trace clips nothing here, the stop excepted.
    bool automaticAperture = false;
    double obscurationRadius = 0;  // central obscuration, mm (0: none)
    bool isStop = false;
    bool mirror = false;        // reflects: the ray turns back, in the medium it came through
    Coating coating;            // as the prescription gives it, else the default (buildLensSystem)
    int line = 0;               // source line in the lens table
    SurfaceForm form;           // odd and Q-type aspheres (EvenAsphere: the terms above)
    std::optional<SurfaceAperture> clearShape;        // replaces the circle of apertureRadius
    std::optional<SurfaceAperture> obscurationShape;  // replaces the circle of obscurationRadius
    // Coordinates arriving at the surface -> its own frame (vertex at (0, 0, z)), and its frame ->
    // the coordinates the next surface (or the film) is placed in. Identity for a centred surface.
    RigidMotion before, after;
    std::optional<FrameChange> frame;  // the decentre and tilt as the file states them (before and after come of it)
    std::string name;           // the file's label, if any

    bool isAspheric() const;     // has polynomial terms
    bool isConic() const { return conic != 0; }
    // Curvature at the vertex, which is all the paraxial (first-order) optics sees: c + 2 a_2.
    double vertexCurvature() const;
    bool isMoved() const { return !before.isIdentity() || !after.isIdentity(); }
    // Traced by the general step: a frame of its own, a shaped aperture or a form beyond the even asphere.
    bool needsGeneralStep() const { return clearShape || obscurationShape || !form.isEvenAsphere(); }
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
    std::optional<double> objectNumericalAperture;
    std::vector<double> wavelengths, wavelengthWeights;  // the file's own, nm (may be empty)
    DesignFields fields;                                 // the file's own field list
    double objectDistance = std::numeric_limits<double>::infinity();  // first surface to object, mm
    // The film's own tilt and decentre in image space (the file's image surface): film coordinates
    // from image-space ones. Identity: the film is the plane z = const across the axis.
    RigidMotion imageFrame;
    // The file decentres or tilts some surface: the trace then meets a surface wherever it lies along
    // the ray's line, behind the ray too, as the design programs do (SurfaceStep.h, kVirtual).
    bool decentred = false;
    std::vector<LensWarning> warnings;  // what the designer should look at; the lens still works

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
    bool hasMovedSurfaces() const;   // some surface's coordinates move (decentres, tilts, a mirrored image space)
    // Every surface centred, circular and even: the trace's fast path holds for all of them.
    bool isRotationallySymmetric() const;
};

// Surface sag at height h (how far the surface lies toward the film from its vertex plane): the even
// asphere c h^2 / (1 + sqrt(1 - (1 + k) c^2 h^2)) + sum a_i h^(2i), or the surface's other form
// (SurfaceSag.h). NaN beyond where it is defined.
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
// table's line for: a coating that does not parse or sits on a mirror, no stop or more than one, a
// diameter larger than the surface's sag allows, an unknown glass (naming the catalogs searched), a
// catalog glass whose nd contradicts the table's N. Warns (LensSystem::warnings) where surfaces
// overlap at their stated diameters and where a moulded glass is taken as its base glass.
LensSystem buildLensSystem(const LensTable& table);

// readLensTable + buildLensSystem.
LensSystem loadLensSystem(const std::string& path, std::optional<TableLayout> layout = std::nullopt);

// The same lens with the aperture stop opened or closed to `diameter` (mm).
LensSystem withStopDiameter(const LensSystem& lens, double diameter);

}  // namespace lenslab
