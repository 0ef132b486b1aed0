#include "LensLayout.h"

#include "trace/ExactTrace.h"

namespace lenslab {

ZY LensLayout::place(const RigidMotion& space, const std::array<double, 3>& p) {
    if (space.isIdentity()) return {p[2], p[1]};
    const auto q = space.applyToPoint(p);
    return {q[2], q[1]};
}

LensLayout layOutLens(const LensSystem& lens) {
    LensLayout layout;
    RigidMotion toDrawing;
    for (const Surface& s : lens.surfaces) {
        if (const RigidMotion into = motionInto(s, TraceDirection::SceneToFilm); !into.isIdentity())
            toDrawing = into.inverse().then(toDrawing);
        layout.own.push_back(toDrawing);
        if (const RigidMotion out = motionOutOf(s, TraceDirection::SceneToFilm); !out.isIdentity())
            toDrawing = out.inverse().then(toDrawing);
        layout.moved |= s.isMoved();
    }
    layout.imageSpace = toDrawing;
    return layout;
}

ZY intoSpace(const RigidMotion& space, ZY p) {
    if (space.isIdentity()) return p;
    const auto q = space.inverse().applyToPoint({0, p.y, p.z});
    return {q[2], q[1]};
}

}  // namespace lenslab
