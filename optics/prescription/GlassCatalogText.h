#pragma once
// The text of optics/data/glass-catalog.tsv, compiled into the library (EmbedText.cmake).

namespace lenslab {

extern const char kGlassCatalogText[];

}  // namespace lenslab
