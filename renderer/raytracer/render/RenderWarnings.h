#pragma once
// What a render's picture does not show, said beside it (issue 38: no silent wrong answer): a
// frame whose camera rays the lens mostly blocks is dark or black, a lens whose image circle is
// smaller than the film leaves the frame black beyond it.
#include <string>
#include <vector>

#include "Render.h"

namespace lenslab {

class PreparedFrame;

// Past this share of blocked camera rays a render says its picture is mostly dark.
constexpr double kMostCameraRaysBlocked = 0.5;

// The warnings of a finished render from its counts and its camera's own (Camera::warnings).
std::vector<std::string> renderWarnings(const RenderStats& stats, const std::vector<std::string>& cameraWarnings);

// Sets output.warnings from output.stats and the frame's camera: the last step of every render,
// one process or many.
void addRenderWarnings(RenderOutput& output, const PreparedFrame& frame);

}  // namespace lenslab
