#pragma once
// A surface's anti-reflection coating: thin dielectric layers, written as text wherever a
// prescription is (a lens table's coat= field, a .zmx COAT line, the editor, the API):
//
//     none                      bare glass (Fresnel reflection only)
//     MgF2   MgF2@550  1.38@510  one quarter-wave layer of a material (a name or an index) at a
//                               design wavelength in nm (default 550)
//     MgF2+ZrO2:2q+Al2O3:80nm@550   a stack: layers from the air side inward, each a quarter wave
//                               unless given as a multiple of one (2q: a half wave) or in nm
//
// The layers run from the coating's outer side, the air side of the surface (as Zemax orders them),
// so that one text means the same coating on a front and a rear surface. Thin films' own
// dispersion is not modelled: each layer keeps its index at every wavelength.
#include <stdexcept>
#include <string>
#include <vector>

namespace lenslab {

struct CoatingLayer {
    double index = 1;        // the film's refractive index
    double thicknessNm = 0;  // physical thickness
};

struct Coating {
    std::string text = "none";        // as written (or the default's text)
    std::vector<CoatingLayer> layers;  // outer (air) side first; empty: bare
    bool isDefault = false;            // given by the default rule, not by the prescription
    bool bare() const { return layers.empty(); }
};

// The design wavelength of a layer written without one (nm), and the default coating of a real
// lens's air-glass surfaces: a quarter wave of MgF2 there.
constexpr double kCoatingDesignNm = 550;
constexpr const char* kDefaultCoatingText = "MgF2@550";

class CoatingError : public std::invalid_argument {
public:
    using std::invalid_argument::invalid_argument;
};

// Parses the text above (material names case-insensitive: Zemax writes MGF2). Throws CoatingError
// naming the problem (an unknown material lists the known ones).
Coating parseCoating(const std::string& text);

// The named thin-film materials and their indices near 550 nm, for messages and the editor.
std::string coatingMaterialNames();

}  // namespace lenslab
