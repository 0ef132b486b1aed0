#pragma once
// Tells a pbrt-v4 scene from a pbrt-v3 one by its main file's text (docs/pbrt-v4.md): pbrt-v4 when
// it holds a directive only pbrt-v4 has (ColorSpace, Option, Attribute, Import), a material, film,
// shape or camera only pbrt-v4 names (Material "diffuse", "string type" "conductor", Film "rgb",
// Shape "bilinearmesh", Camera "spherical"), or a light parameter only pbrt-v4 reads ("power",
// "illuminance"); pbrt-v3 otherwise. Files it includes are read in the same dialect.
#include <vector>

#include "core/SceneDialect.h"
#include "scene/SceneTokenizer.h"

namespace lenslab {

SceneDialect detectDialect(const std::vector<Token>& tokens);

}  // namespace lenslab
