#include "TextRaster.h"

#include <ft2build.h>
#include FT_FREETYPE_H

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>
#include <utility>

#include "LensDiagram.h"

namespace lenslab {

namespace {

struct Glyph {
    int width = 0, rows = 0, left = 0, top = 0;
    double advance = 0;
    std::vector<std::uint8_t> coverage;
};

// The face and the glyphs rasterised so far. Glyphs are never removed, so pointers handed out
// under the lock stay valid after it is released.
class GlyphCache {
public:
    static GlyphCache& instance() {
        static GlyphCache cache;
        return cache;
    }

    std::vector<const Glyph*> glyphs(const std::u32string& text, int pixelSize) {
        std::lock_guard<std::mutex> lock(mutex_);
        if (!error_.empty()) throw DiagramError(error_);
        std::vector<const Glyph*> out;
        for (char32_t c : text) {
            auto key = std::make_pair(pixelSize, c);
            auto it = glyphs_.find(key);
            if (it == glyphs_.end()) it = glyphs_.emplace(key, rasterise(c, pixelSize)).first;
            out.push_back(&it->second);
        }
        return out;
    }

private:
    GlyphCache() {
        if (FT_Init_FreeType(&library_) != 0) {
            error_ = "diagram text: FreeType does not start";
        } else if (FT_New_Face(library_, LENSLAB_FONT_PATH, 0, &face_) != 0) {
            error_ = std::string("diagram text: cannot load the font ") + LENSLAB_FONT_PATH +
                     " (Debian package fonts-dejavu-core)";
        }
    }
    ~GlyphCache() {
        if (face_) FT_Done_Face(face_);
        if (library_) FT_Done_FreeType(library_);
    }

    Glyph rasterise(char32_t c, int pixelSize) {
        Glyph g;
        FT_Set_Pixel_Sizes(face_, 0, static_cast<FT_UInt>(pixelSize));
        if (FT_Load_Char(face_, c, FT_LOAD_RENDER | FT_LOAD_TARGET_LIGHT) != 0) return g;
        const FT_GlyphSlot slot = face_->glyph;
        const FT_Bitmap& bitmap = slot->bitmap;
        g.width = static_cast<int>(bitmap.width);
        g.rows = static_cast<int>(bitmap.rows);
        g.left = slot->bitmap_left;
        g.top = slot->bitmap_top;
        g.advance = slot->advance.x / 64.0;
        g.coverage.resize(static_cast<std::size_t>(g.width) * g.rows);
        for (int y = 0; y < g.rows; ++y)
            std::copy_n(bitmap.buffer + y * bitmap.pitch, g.width, g.coverage.begin() + static_cast<std::ptrdiff_t>(y) * g.width);
        return g;
    }

    std::mutex mutex_;
    FT_Library library_ = nullptr;
    FT_Face face_ = nullptr;
    std::string error_;
    std::map<std::pair<int, char32_t>, Glyph> glyphs_;
};

std::u32string decodeUtf8(const std::string& text) {
    std::u32string out;
    for (std::size_t i = 0; i < text.size();) {
        const auto b = static_cast<unsigned char>(text[i]);
        const int extra = b >= 0xF0 ? 3 : b >= 0xE0 ? 2 : b >= 0xC0 ? 1 : 0;
        char32_t c = extra == 0 ? b : b & (0x3F >> extra);
        for (int k = 1; k <= extra && i + k < text.size(); ++k) c = (c << 6) | (static_cast<unsigned char>(text[i + k]) & 0x3F);
        out.push_back(c);
        i += 1 + extra;
    }
    return out;
}

double advanceOf(const std::vector<const Glyph*>& glyphs) {
    double w = 0;
    for (const Glyph* g : glyphs) w += g->advance;
    return w;
}

// A label's coverage in its own small bitmap, with a margin of one pixel for the halo.
struct LabelBitmap {
    int x0 = 0, y0 = 0, width = 0, height = 0;
    std::vector<std::uint8_t> coverage;
};

LabelBitmap rasteriseLabel(const TextLabel& label) {
    const std::vector<const Glyph*> glyphs = GlyphCache::instance().glyphs(decodeUtf8(label.text), label.pixelSize);
    const double width = advanceOf(glyphs);
    double penX = label.at.x - (label.anchor == TextAnchor::Left ? 0 : label.anchor == TextAnchor::Centre ? width / 2 : width);
    const int baseline = static_cast<int>(std::lround(label.at.y));
    LabelBitmap b;
    b.x0 = static_cast<int>(std::floor(penX)) - 2;
    b.y0 = baseline - label.pixelSize - 2;
    b.width = static_cast<int>(std::ceil(width)) + 4 + label.pixelSize / 2;
    b.height = label.pixelSize * 3 / 2 + 4;
    b.coverage.assign(static_cast<std::size_t>(b.width) * b.height, 0);
    for (const Glyph* g : glyphs) {
        const int gx = static_cast<int>(std::lround(penX)) + g->left - b.x0;
        const int gy = baseline - g->top - b.y0;
        for (int y = 0; y < g->rows; ++y)
            for (int x = 0; x < g->width; ++x) {
                const int bx = gx + x, by = gy + y;
                if (bx < 0 || by < 0 || bx >= b.width || by >= b.height) continue;
                std::uint8_t& dst = b.coverage[static_cast<std::size_t>(by) * b.width + bx];
                dst = std::max(dst, g->coverage[static_cast<std::size_t>(y) * g->width + x]);
            }
        penX += g->advance;
    }
    return b;
}

void blend(std::uint8_t* pixel, Rgba colour, int coverage) {
    const int a = coverage * colour.a / 255;
    pixel[0] = static_cast<std::uint8_t>((colour.r * a + pixel[0] * (255 - a)) / 255);
    pixel[1] = static_cast<std::uint8_t>((colour.g * a + pixel[1] * (255 - a)) / 255);
    pixel[2] = static_cast<std::uint8_t>((colour.b * a + pixel[2] * (255 - a)) / 255);
}

}  // namespace

double textWidth(const std::string& text, int pixelSize) {
    return advanceOf(GlyphCache::instance().glyphs(decodeUtf8(text), pixelSize));
}

void drawTextLabels(std::vector<std::uint8_t>& pixels, int width, int height, const std::vector<TextLabel>& labels,
                    Rgba halo) {
    for (const TextLabel& label : labels) {
        const LabelBitmap b = rasteriseLabel(label);
        auto coverageAt = [&](int x, int y) {
            return x < 0 || y < 0 || x >= b.width || y >= b.height ? 0 : b.coverage[static_cast<std::size_t>(y) * b.width + x];
        };
        for (int y = 0; y < b.height; ++y) {
            const int py = b.y0 + y;
            if (py < 0 || py >= height) continue;
            for (int x = 0; x < b.width; ++x) {
                const int px = b.x0 + x;
                if (px < 0 || px >= width) continue;
                int spread = 0;  // the halo: coverage dilated by one pixel
                for (int dy = -1; dy <= 1; ++dy)
                    for (int dx = -1; dx <= 1; ++dx) spread = std::max(spread, static_cast<int>(coverageAt(x + dx, y + dy)));
                std::uint8_t* pixel = &pixels[(static_cast<std::size_t>(py) * width + px) * 4];
                if (spread > 0) blend(pixel, halo, spread);
                if (const int c = coverageAt(x, y)) blend(pixel, label.colour, c);
            }
        }
    }
}

}  // namespace lenslab
