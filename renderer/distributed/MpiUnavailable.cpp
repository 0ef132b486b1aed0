// renderSceneOverMpi in a build without Open MPI: a clear error instead of a missing option.
#include <stdexcept>

#include "MpiRender.h"

namespace lenslab {

bool mpiAvailable() { return false; }

std::optional<RenderOutput> renderSceneOverMpi(const RenderSettings&, const MpiRenderOptions&,
                                               const std::function<void(const TileUpdate&, const Image&)>&) {
    throw std::runtime_error("this lenslab was built without MPI (install openmpi-bin and libopenmpi-dev, then rebuild)");
}

}  // namespace lenslab
