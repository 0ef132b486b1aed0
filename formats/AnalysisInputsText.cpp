#include "AnalysisInputsText.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>

#include "analysis/LensDesignAnalysis.h"
#include "prescription/LensTable.h"

namespace lenslab {

namespace {

// Comma-separated items, none empty; at most `limit` of them (the analysis bounds its work).
std::vector<std::string> splitList(const std::string& text, const std::string& source, int limit) {
    std::vector<std::string> items;
    std::size_t start = 0;
    while (true) {
        const std::size_t comma = text.find(',', start);
        std::string item = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
        const std::size_t b = item.find_first_not_of(" \t"), e = item.find_last_not_of(" \t");
        item = b == std::string::npos ? "" : item.substr(b, e - b + 1);
        if (item.empty()) throw InputListError(source + ": empty item in '" + text.substr(0, 80) + "'");
        items.push_back(item);
        if (int(items.size()) > limit)
            throw InputListError(source + ": at most " + std::to_string(limit) + " values");
        if (comma == std::string::npos) return items;
        start = comma + 1;
    }
}

double number(const std::string& item, const std::string& source) {
    char* end = nullptr;
    errno = 0;
    const double v = std::strtod(item.c_str(), &end);
    if (*end != '\0' || errno == ERANGE || !std::isfinite(v))
        throw InputListError(source + ": '" + item.substr(0, 40) + "' is not a number");
    return v;
}

}  // namespace

std::vector<double> parseWavelengthList(const std::string& text, const std::string& source) {
    std::vector<double> nm;
    for (const std::string& item : splitList(text, source, kMaxAnalysisWavelengths)) {
        if (item == "F") nm.push_back(kWavelengthF);
        else if (item == "d") nm.push_back(kWavelengthD);
        else if (item == "C") nm.push_back(kWavelengthC);
        else nm.push_back(number(item, source + " (F, d, C or nm)"));
    }
    return nm;
}

FieldList parseFieldList(const std::string& text, const std::string& source) {
    FieldList fields;
    for (std::string item : splitList(text, source, kMaxAnalysisFields)) {
        if (item.size() > 3 && item.compare(item.size() - 3, 3, "deg") == 0) {
            fields.degrees = true;
            item.erase(item.size() - 3);
        }
        fields.values.push_back(number(item, source));
    }
    return fields;
}

ImagePlane parseImagePlaneInput(const std::string& text, const std::string& source) {
    if (const std::optional<ImagePlane> plane = parseImagePlane(text)) return *plane;
    throw InputListError(source + ": the image plane is paraxial, film or best");
}

SpotReference parseSpotReferenceInput(const std::string& text, const std::string& source) {
    if (const std::optional<SpotReference> reference = parseSpotReference(text)) return *reference;
    throw InputListError(source + ": the reference point is centroid or chief");
}

}  // namespace lenslab
