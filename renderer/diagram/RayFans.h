#pragma once
// Ray fans for the diagram, drawn forward as light travels: from the object (or, for a distant or
// out-of-view object, from a plane in front of the lens) through the sequential trace, mirrors and
// all, to the film. Each fan is one field's meridional rays, aimed at evenly spaced heights across
// the aperture stop and a little beyond it, so the outer rays show the stop. Paths are in lens mm,
// where the drawing shows them: a folded or decentred lens's as laid out in space (LensLayout.h).
#include <vector>

#include "settings/LensAnalysis.h"
#include "LensOutline.h"
#include "MirrorSolids.h"

namespace lenslab {

enum class RayModel { Exact, Thick };

struct FanRay {
    std::vector<ZY> points;  // the object side first
    RayModel model = RayModel::Exact;
    bool offAxis = false;    // from the off-axis field rather than the axis
    bool blocked = false;    // the last point is where the lens stopped it
    double wavelength = 0;   // nm, for the F, d and C fans; 0: the analysis's own wavelength
};

struct FanSetup {
    double filmZ = 0;         // in image space (after the last surface)
    double fieldDegrees = 0;  // the off-axis fan's field (object space, toward +y); 0: the axial fan only
    int rays = 9;
    double startZ = 0;        // object space: where rays start when the object is farther off than this (infinity included)
    MirrorBores bores;        // holes the light passes through mirrors (MirrorSolids.h); empty: none
};

// The fans aim across the stop's diameter and a little beyond it, so the outer rays show the stop.
constexpr double kFanOverfill = 1.2;

// One fan per field (the axis, then the off-axis field): rays k = 0..n-1 aimed at stop heights
// (-1 + 2k / (n - 1)) kFanOverfill times the stop's radius. Both models trace the same incoming rays,
// ray for ray. Exact rays stop where a surface blocks them or where they would cross a mirror's solid
// part (its back: the obscuration a sequential trace does not see); the thick lens's at its entrance
// pupil. A field with no ray through the stop's centre draws no fan.
std::vector<FanRay> traceRayFans(const LensAnalysis& analysis, RayModel model, const FanSetup& setup);

// The exact fans at the F, d and C lines: the same incoming rays, each line's indices, so the colour
// spread shows where they leave the glass.
std::vector<FanRay> traceColourFans(const LensAnalysis& analysis, const FanSetup& setup);

// The object field whose chief ray (every aperture and obscuration ignored) reaches the film at
// `height` mm below the axis; the widest traceable field when none reaches that far. Degrees.
double fieldForFilmHeight(const LensAnalysis& analysis, double filmZ, double height);

// How far below the axis the field's chief ray reaches the film (apertures ignored); 0 when no chief
// ray exists.
double chiefFilmHeight(const LensAnalysis& analysis, double filmZ, double fieldDegrees);

// The off-axis fan's field when none is asked: 70% of the lens's largest field (LensAnalysis::field);
// for a lens that defines none, the field imaged at half its largest clear radius (paraxially).
double automaticFanField(const LensAnalysis& analysis);

// The optical axis as a folded or decentred lens's drawing shows it: the axial field's ray through the
// centre of the stop (the axis ray its first order is measured along), every aperture ignored, from
// the start to the film (as far as it gets).
std::vector<ZY> opticalAxisPath(const LensAnalysis& analysis, const FanSetup& setup);

// Where the light of the drawn fields (the axis and the off-axis fan's field) runs through the
// sequential trace: full-aperture meridional fans, exact, the paths of the rays that reach the film as
// if no mirror stood in their way. MirrorSolids finds the holes this light needs. Not the lens's
// largest field: where nothing but the hole limits it (a Schmidt-Cassegrain's chief ray passes every
// rim to several degrees), the hole its light needed would swallow the drawn fans.
std::vector<std::vector<ZY>> passingLightPaths(const LensAnalysis& analysis, const FanSetup& setup);

}  // namespace lenslab
