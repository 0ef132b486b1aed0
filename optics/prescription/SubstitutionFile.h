#pragma once
// A file-level glass substitution table beside a prescription, in ray-optics' .smx form: a JSON
// object from the glass name the prescription writes to what to use for it:
//   "BK7": ["N-BK7", "Schott"]                                    a catalog glass and its catalog
//   "SILICA": "om.ConstantIndex(1.5086, 'SILICA')"                a constant index
//   "D-ZK3M": "om.InterpolatedMedium('D-ZK3M', pairs=[(587.6, 1.586), ...])"  measured indices (nm, n)
//   "C79-80": "gfact.create_glass('https://refractiveindex.info/database/data/main/SiO2/nk/Malitson.yml', 'rindexinfo')"
//                                                                  a refractiveindex.info material lenslab bundles
#include <optional>
#include <string>
#include <vector>

#include "prescription/LensTable.h"

namespace lenslab {

// Throws LensTableError naming the file, the entry's line and the problem.
std::vector<GlassSubstitute> parseSubstitutionFile(const std::string& text, const std::string& fileName);

// The table beside a prescription file: the same path with the extension .smx, if it exists.
std::optional<std::string> substitutionFileFor(const std::string& prescriptionPath);

}  // namespace lenslab
