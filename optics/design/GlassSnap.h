#pragma once
// Model glasses (nd, Vd) made real: after an optimisation has moved a glass's nd and Vd, the nearest
// catalog glass takes its place. Nearness weighs 0.01 in nd as 1 in Vd (a glass map's usual
// aspect: the catalogs spread about 0.01 in nd for each unit of Vd), so the distance is
// hypot(100 (nd - nd0), Vd - Vd0).
#include <optional>
#include <string>
#include <vector>

#include "prescription/LensTable.h"

namespace lenslab {

struct GlassChoice {
    int row = 0;              // 0-based
    double nd = 0, vd = 0;    // the model glass replaced
    Medium glass;             // the catalog glass chosen (its name and catalog)
    double distance = 0;      // hypot(100 dnd, dVd)
};

// The catalog glass nearest (nd, vd) among the named catalogs (every bundled and loaded one when
// none is named); nullopt when the catalogs named hold no glass.
std::optional<Medium> nearestCatalogGlass(double nd, double vd, const std::vector<std::string>& catalogs = {});

// Each row of `rows` that holds a model glass (nd and Vd, no name) takes its nearest catalog glass;
// the choices, in row order. Rows with a named glass or air are left as they are.
std::vector<GlassChoice> snapToCatalogGlasses(LensTable& table, const std::vector<int>& rows,
                                              const std::vector<std::string>& catalogs = {});

}  // namespace lenslab
