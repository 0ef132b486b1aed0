#pragma once
// The report's renders: each lens through each scene with a realistic camera, accurate and
// approximate, their difference image, and the speed-against-accuracy study. Every render is an
// item of the cache, keyed by the scene's files, the lens table and the settings.
#include <string>
#include <vector>

#include "BuildReport.h"
#include "ItemRunner.h"
#include "ReportContent.h"

namespace lenslab {

// The settings every render of the report shares.
struct RenderPlan {
    int spp = 0, width = 0;
    // Lens flare in the scenes that ask for it: exact, or paraxial in a quick build (the exact model's
    // setup, seconds per lens, would outweigh its tiny renders).
    std::string ghostModel = "exact";
    std::vector<int> speedSpps;  // the sample counts of the speed study: 1, 2, 4, ... up to spp / 4
};

RenderPlan renderPlan(const ReportOptions& options);

RenderPair buildRenderPair(ItemRunner& runner, const SceneSource& scene, const LensEntry& lens, const RenderPlan& plan,
                           const ReportOptions& options);

// The scene that shows lateral colour (scenes/lateral-colour-chart.pbrt), by its id.
constexpr const char* kColourChartSceneId = "lateral-colour-chart";

// A dispersive lens through the colour chart, exact, spectral and RGB.
ColourFringes buildColourFringes(ItemRunner& runner, const SceneSource& chart, const LensEntry& lens,
                                 const RenderPlan& plan, const ReportOptions& options);

// Lower sample counts of `lens` in the scene against its accurate render at the plan's count (taken
// from scene.pairs; the study is empty when that render is missing).
SpeedStudy buildSpeedStudy(ItemRunner& runner, const ReportScene& scene, const LensEntry& lens, const RenderPlan& plan,
                           const ReportOptions& options);

// The scene the sensor's ISO ladder is cropped from, by its id, and the ladder's ISO speeds.
constexpr const char* kSensorLadderSceneId = "depth-of-field";
constexpr double kSensorLadderIsos[] = {100, 400, 1600, 6400, 25600};

// `lens` in that scene behind a sensor at each ISO: crops of plan.width pixels at 4.35 um.
SensorLadder buildSensorLadder(ItemRunner& runner, const SceneSource& scene, const LensEntry& lens, const RenderPlan& plan,
                               const ReportOptions& options);

}  // namespace lenslab
