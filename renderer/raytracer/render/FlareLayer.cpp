#include "render/FlareLayer.h"

#include <map>

#include "render/FlareSources.h"

namespace lenslab {

FlareLayer makeFlareLayer(const Camera& camera, const CameraOverrides& overrides, const SceneGeometry& geometry, int width,
                          int height, const SpectralSensor& sensor, float time, const std::atomic<bool>* cancel) {
    FlareLayer layer;
    const auto* realistic = dynamic_cast<const RealisticCamera*>(&camera);
    if (!realistic) {
        const std::optional<GhostSelection> asked = overrides.ghosts ? parseGhostSelection(*overrides.ghosts) : std::nullopt;
        if (asked && asked->on() && asked->mode != GhostSelection::Mode::Auto)
            throw SceneError("ghosts need a still camera: this one moves during the exposure");
        return layer;
    }
    const GhostSelection& selection = realistic->params().ghosts;
    if (!selection.on()) return layer;
    const bool automatic = selection.mode == GhostSelection::Mode::Auto;
    const std::vector<FlareSource> sources = findFlareSources(geometry, *realistic, width, height, sensor, automatic, time);
    if (sources.empty() && automatic) return layer;
    layer.rgb = renderLensFlare(*realistic, width, height, sources, selectGhostPaths(*realistic, selection, cancel),
                                selection.model, layer.stats, cancel);
    std::map<std::string, int> kinds;
    for (const FlareSource& s : sources) ++kinds[s.what];
    std::string what;
    for (const auto& [kind, count] : kinds) what += (what.empty() ? "" : ", ") + std::to_string(count) + " " + kind;
    layer.description = std::string(ghostModelName(selection.model)) + " ghosts (" + ghostSelectionName(selection) + "): " +
                        std::to_string(layer.stats.paths) + " paths of " + (what.empty() ? "no emitter" : what) + ", " +
                        std::to_string(layer.stats.raysTraced) + " rays, " + std::to_string(layer.stats.seconds) + " s";
    return layer;
}

}  // namespace lenslab
