#pragma once
// Where each space of a lens lies in the diagram's coordinates. The diagram is drawn in object space
// (the coordinates a ray starts in, in which the trace records its path): every surface's own frame,
// and the image space, carried back through the motions before them. A
// folded or decentred system is so drawn as it is laid out; a lens whose surfaces never move has the
// identity everywhere and is drawn along its axis as always. Points project onto the (z, y) plane.
#include <array>
#include <vector>

#include "prescription/LensSystem.h"
#include "LensOutline.h"

namespace lenslab {

struct LensLayout {
    std::vector<RigidMotion> own;       // surface i's own frame (vertex at (0, 0, z)) -> the drawing's
    RigidMotion imageSpace;             // the coordinates after the last surface (film, F', P') -> the drawing's
    bool moved = false;                 // some motion is not the identity

    // A point of a space to the drawing's (z, y); the identity gives the point's own (z, y) exactly.
    static ZY place(const RigidMotion& space, const std::array<double, 3>& p);
    ZY inImageSpace(double y, double z) const { return place(imageSpace, {0, y, z}); }
};

LensLayout layOutLens(const LensSystem& lens);

// A drawn point (x = 0 in the drawing) in the coordinates of a space placed by `space`: the (z, y)
// of its image under the inverse motion. Exact for the meridional section of a lens moved in it
// (decentres along y, tilts about x); the identity returns the point unchanged.
ZY intoSpace(const RigidMotion& space, ZY p);

}  // namespace lenslab
