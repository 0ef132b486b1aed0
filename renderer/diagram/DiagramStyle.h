#pragma once
// Colours of the diagram, shared by the drawing and by the tests that look for them.
#include "DrawList.h"

namespace lenslab::diagram_style {

constexpr Rgba kBackground{255, 255, 255, 255};
constexpr Rgba kGlass{204, 227, 247, 255};         // light blue tint between surfaces
constexpr Rgba kLensLine{38, 52, 78, 255};
constexpr Rgba kAxis{110, 110, 110, 255};
constexpr Rgba kStop{20, 20, 20, 255};
constexpr Rgba kFilm{150, 75, 0, 255};
constexpr Rgba kCardinal{165, 35, 140, 255};       // F, F', P, P'
constexpr Rgba kPupil{20, 140, 70, 255};
constexpr Rgba kExactRay{25, 95, 215, 255};        // blue
constexpr Rgba kThickRay{235, 115, 10, 255};       // orange
constexpr Rgba kMirror{70, 70, 80, 255};           // a reflecting surface, drawn heavy
// The Fraunhofer lines' fans: F (486 nm) cyan-blue, d (588 nm) a yellow dark enough on white, C
// (656 nm) red; each far enough from the exact rays' blue and the block mark's red to be told apart.
constexpr Rgba kLineF{0, 150, 190, 255};
constexpr Rgba kLineD{185, 150, 0, 255};
constexpr Rgba kLineC{235, 45, 0, 255};
constexpr Rgba kBlockMark{205, 25, 25, 255};       // the cross where a ray is stopped
constexpr Rgba kText{25, 25, 25, 255};
constexpr Rgba kNote{95, 95, 95, 255};
constexpr Rgba kLeader{175, 175, 175, 255};

// Blocked rays keep their model's hue, faded, so overlay mode still tells them apart.
constexpr Rgba faded(Rgba c) { return {c.r, c.g, c.b, 110}; }

}  // namespace lenslab::diagram_style
