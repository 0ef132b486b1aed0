#pragma once
// Text for the diagram: glyphs rasterised by FreeType from a DejaVu Sans file and blended into the
// read-back picture, with a light halo so labels stay readable over lines. Thread-safe: one face,
// one glyph cache, guarded by a lock.
#include <cstdint>
#include <string>
#include <vector>

#include "DrawList.h"

namespace lenslab {

enum class TextAnchor { Left, Centre, Right };

struct TextLabel {
    Point2 at;            // baseline point; x is the left end, centre or right end per `anchor`
    std::string text;     // UTF-8
    int pixelSize = 14;   // em size in pixels
    Rgba colour;
    TextAnchor anchor = TextAnchor::Left;
};

// Advance width of the text in pixels. Throws DiagramError when the font cannot be loaded.
double textWidth(const std::string& text, int pixelSize);

// Blends the labels into width*height RGBA8 pixels (top row first).
void drawTextLabels(std::vector<std::uint8_t>& pixels, int width, int height, const std::vector<TextLabel>& labels,
                    Rgba halo);

}  // namespace lenslab
