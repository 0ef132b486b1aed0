#pragma once
// Which pbrt generation a scene is written for. Some names mean different things in pbrt-v3 and
// pbrt-v4 (how a light's spectrum is normalised, how an environment map is laid out, a spot's
// falloff, the realistic camera's exposure, the film's sensor), so the factories that read them
// are told which (docs/pbrt-v4.md; scene/DialectDetection.h decides).
namespace lenslab {

enum class SceneDialect { PbrtV3, PbrtV4 };

}  // namespace lenslab
