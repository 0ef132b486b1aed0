#pragma once
// The solid parts of mirrors, as the diagram draws them. A sequential trace meets a mirror only where
// its rays reflect from it, and lets every other ray pass through the mirror's place: the light
// coming back from a Cassegrain's secondary through the primary, the light from the scene through
// the back of the secondary. A real instrument has a hole (a bore) in the first and a shadow behind
// the second. So the diagram gives each mirror the bore the passing light and the elements set inside
// it need, and stops a ray where it would cross a mirror's solid part. Lens millimetres, (z, y) of the
// drawing (LensLayout.h); each mirror is judged in its own frame.
#include <optional>
#include <vector>

#include "prescription/LensSystem.h"
#include "LensLayout.h"
#include "LensOutline.h"

namespace lenslab {

// Per surface, the radius of the hole through it (0: none). Every surface of a mirror's element (a
// Mangin mirror's glass faces and its silvered one) has the mirror's bore.
struct MirrorBores {
    std::vector<double> radius;
    double at(int surface) const { return surface < static_cast<int>(radius.size()) ? radius[surface] : 0.0; }
};

// The surfaces of the element mirror `surface` belongs to: itself and its neighbours joined to it by
// glass, in order.
std::vector<int> mirrorElement(const LensSystem& lens, int surface);

// The bores: for each mirror, the largest of its own obscuration (a hole the prescription states),
// the heights where `passingLight` (each path the start, every surface's hit in order, then the film)
// crosses its element coming from the mirror's reflecting side (not at its own hits, nor on its way to
// the mirror through the diaphragms just before it), and the clear radius of any other surface set
// inside the element (diaphragms aside).
MirrorBores findMirrorBores(const LensSystem& lens, const LensLayout& layout, const std::vector<std::vector<ZY>>& passingLight);

// The first point strictly between a and b where the segment crosses a mirror's solid part (between
// its bore and its clear radius); nullopt when it crosses none.
std::optional<ZY> firstSolidMirrorCrossing(const LensSystem& lens, const LensLayout& layout, const MirrorBores& bores, ZY a, ZY b);

}  // namespace lenslab
