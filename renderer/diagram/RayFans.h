#pragma once
// Ray fans for the diagram, traced like the course's reference tool: from points on the film
// (on the axis and at a field height) toward the scene, through the exact lens or its thick-lens
// model, until they reach the focus in front of it. Paths are in lens millimetres.
#include <vector>

#include "settings/LensAnalysis.h"
#include "LensOutline.h"

namespace lenslab {

enum class RayModel { Exact, Thick };

struct FanRay {
    std::vector<ZY> points;  // film point first
    RayModel model = RayModel::Exact;
    bool offAxis = false;    // from the field point rather than the axis
    bool blocked = false;    // the last point is where the lens stopped it
    double wavelength = 0;   // nm, for the F, d and C fans; 0: the analysis's own wavelength
};

struct FanSetup {
    double filmZ = 0;
    double fieldHeight = 0;  // mm on the film; the field point sits below the axis; 0: axial fan only
    int rays = 9;
    double endZ = 0;         // where unblocked rays end in front of the lens
};

// The fans aim across the exit pupil and a little beyond it, so the outer rays show the stop.
constexpr double kFanOverfill = 1.2;

std::vector<FanRay> traceRayFans(const LensAnalysis& analysis, RayModel model, const FanSetup& setup);

// The exact fans at the F, d and C lines (the same film points, each line's indices), so the colour
// spread shows where they leave the lens.
std::vector<FanRay> traceColourFans(const LensAnalysis& analysis, const FanSetup& setup);

// Film height for the off-axis fan when none is given: 70% of the largest height whose chief ray
// (aimed at the centre of the exit pupil) still passes the real lens.
double automaticFieldHeight(const LensAnalysis& analysis, double filmZ);

}  // namespace lenslab
