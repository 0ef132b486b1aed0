#pragma once
// Zemax glass catalogs (.agf), as the glass makers publish them: NM (name, formula number, nd, Vd),
// CD (the formula's coefficients), LD (the valid wavelengths), and lines lenslab does not need (CC
// comments, GC, ED thermal expansion and density, TD thermal dispersion, OD, IT transmission).
#include <string>
#include <vector>

#include "prescription/Medium.h"

namespace lenslab {

struct GlassCatalogFile {
    std::string name;            // the catalog's name: the file's stem in upper case ("SCHOTT")
    std::vector<Medium> glasses;
    std::vector<int> formulaNumbers;  // each glass's Zemax formula number (1 to 13), parallel to glasses
};

// Parses an AGF file (ASCII, UTF-8 or UTF-16 with a byte order mark). Every one of Zemax's 13
// dispersion formulas is read:
//   1 Schott        n^2 = a0 + a1 L^2 + a2 L^-2 + a3 L^-4 + a4 L^-6 + a5 L^-8
//   2 Sellmeier 1   n^2 - 1 = K1 L^2/(L^2 - L1) + K2 L^2/(L^2 - L2) + K3 L^2/(L^2 - L3)
//   3 Herzberger    n = A + B M + C M^2 + D L^2 + E L^4 + F L^6, M = 1/(L^2 - 0.028)
//   4 Sellmeier 2   n^2 - 1 = A + B1 L^2/(L^2 - l1^2) + B2/(L^2 - l2^2)
//   5 Conrady       n = n0 + A/L + B/L^3.5
//   6 Sellmeier 3   four Sellmeier 1 terms
//   7 Handbook 1    n^2 = A + B/(L^2 - C) - D L^2
//   8 Handbook 2    n^2 = A + B L^2/(L^2 - C) - D L^2
//   9 Sellmeier 4   n^2 = A + B L^2/(L^2 - C) + D L^2/(L^2 - E)
//  10 Extended      the Schott form with a6 L^-10 + a7 L^-12
//  11 Sellmeier 5   five Sellmeier 1 terms
//  12 Extended 2    the Schott form with a6 L^4 + a7 L^6
//  13 Extended 3    n^2 = a0 + a1 L^2 + a2 L^4 + a3 L^-2 + a4 L^-4 + ... + a8 L^-12
// (L in micrometres; Zemax OpticStudio's manual, "Glass catalogs"). `fileName` names the file in
// messages and gives the catalog's name. Throws LensTableError (file, line, problem).
GlassCatalogFile parseGlassCatalogFile(const std::string& bytes, const std::string& fileName);

// Reads and parses a file. Throws LensTableError (also for unreadable files).
GlassCatalogFile readGlassCatalogFile(const std::string& path);

bool isGlassCatalogFileName(const std::string& name);  // ".agf", any case

}  // namespace lenslab
