#pragma once
// The analysis inputs as people type them, the same on the command line and in query parameters:
// wavelengths "F,d,C" or "486.1,587.6" (Fraunhofer letters or nm), fields "0,0.7,1" (fractions of
// the largest field) or "0,10,20deg" (degrees: a trailing "deg" on the list or any value), the image
// plane and the spots' reference point by name.
#include <stdexcept>
#include <string>
#include <vector>

#include "analysis/LensDesignAnalysis.h"

namespace lenslab {

// A list that is not of that form; the message starts with `source`.
class InputListError : public std::invalid_argument {
public:
    using std::invalid_argument::invalid_argument;
};

std::vector<double> parseWavelengthList(const std::string& text, const std::string& source);

struct FieldList {
    std::vector<double> values;
    bool degrees = false;
};
FieldList parseFieldList(const std::string& text, const std::string& source);

// "paraxial", "film" or "best"; "centroid" or "chief".
ImagePlane parseImagePlaneInput(const std::string& text, const std::string& source);
SpotReference parseSpotReferenceInput(const std::string& text, const std::string& source);

}  // namespace lenslab
