#pragma once
// What the job queue needs from a renderer. The service uses the ray tracer (EngineRenderer); tests
// inject a fast stand-in to exercise queueing, cancellation and recovery.
#include <nlohmann/json.hpp>

#include <atomic>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "Render.h"
#include "jobs/RenderRequest.h"

namespace lenslab {

struct RenderJobInput {
    std::string jobId;
    RenderRequest request;
    std::string scenePath;  // resolved inside the scenes folder
    std::string lensPath;   // resolved inside the lens folders
    TableLayout lensLayout = TableLayout::GapBefore;  // the layout the lens was checked with
};

struct RenderedImages {
    std::vector<std::uint8_t> png, exr;
    nlohmann::json stats = nlohmann::json::object();
    std::vector<std::string> warnings;
};

class JobRenderer {
public:
    using TileCallback = std::function<void(const TileUpdate&, const Image&)>;
    virtual ~JobRenderer() = default;
    // Renders the job; onTile is called (serialised) after each finished tile with the image so
    // far. Throws RenderCancelled once `cancel` turns true, any std::exception on failure.
    virtual RenderedImages render(const RenderJobInput& job, const TileCallback& onTile,
                                  const std::atomic<bool>& cancel) = 0;
    // The partial image as PNG, for the page to draw tiles as they arrive.
    virtual std::vector<std::uint8_t> encodePreview(const Image& partial) const = 0;
};

}  // namespace lenslab
