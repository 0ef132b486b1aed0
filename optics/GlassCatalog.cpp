#include "GlassCatalog.h"

namespace lenslab {

GlassLookup findGlass(const std::string&, const std::vector<std::string>&) { return {}; }

}  // namespace lenslab
