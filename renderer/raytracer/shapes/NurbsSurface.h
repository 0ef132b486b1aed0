#pragma once
// pbrt-v3's "nurbs" shape: a (rational) B-spline surface diced, as pbrt-v3 dices it, into a
// 30 x 30 grid of quads with exact positions, normals and (u, v) at the grid points.
#include "shapes/TriangleMeshShape.h"

namespace lenslab {

// nu, nv, uorder, vorder, uknots, vknots, u0, u1, v0, v1 and "point P" or "float Pw" (x y z w per
// point). Throws SceneError naming the parameter for bad input.
MeshData diceNurbs(const ParamSet& params);

}  // namespace lenslab
