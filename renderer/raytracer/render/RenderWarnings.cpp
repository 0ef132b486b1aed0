#include "render/RenderWarnings.h"

#include "prescription/NumberText.h"
#include "render/PreparedFrame.h"

namespace lenslab {

std::vector<std::string> renderWarnings(const RenderStats& stats, const std::vector<std::string>& cameraWarnings) {
    std::vector<std::string> warnings;
    if (stats.cameraRays > 0) {
        const double blocked = double(stats.blockedCameraRays) / double(stats.cameraRays);
        if (stats.blockedCameraRays == stats.cameraRays)
            warnings.push_back("the lens blocks every camera ray (" + std::to_string(stats.cameraRays) + "): the image is black");
        else if (blocked > kMostCameraRaysBlocked)
            warnings.push_back("the lens blocks " + formatFixed(100 * blocked, 1) + "% of the camera rays: most of the frame is dark");
    }
    warnings.insert(warnings.end(), cameraWarnings.begin(), cameraWarnings.end());
    return warnings;
}

void addRenderWarnings(RenderOutput& output, const PreparedFrame& frame) {
    output.warnings = renderWarnings(output.stats, frame.cameraWarnings());
}

}  // namespace lenslab
