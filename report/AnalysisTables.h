#pragma once
// The analysis's settings and numbers as every view shows them: the web page and the report as
// HTML, `lenslab analyze` as text, from one list. Each value carries where the analysis JSON
// (designAnalysisJson, the API's answer) holds it, so the HTML marks every shown number with its
// JSON pointer and exact value (data-json, data-value, data-scale) and a test can check each one
// against the API's.
#include <string>
#include <utility>
#include <vector>

#include "analysis/LensDesignAnalysis.h"

namespace lenslab {

struct ShownValue {
    std::string text;     // as shown
    std::string pointer;  // JSON pointer into designAnalysisJson's object; empty for a label
    std::string exact;    // the value the JSON holds: a number to 17 significant digits, null, true, false or a word
    double scale = 1;     // text is the value times scale, rounded (micrometres from the JSON's millimetres)
};

struct AnalysisSetting {
    std::string name;
    ShownValue value;
    std::string unit;
};

struct AnalysisTable {
    std::string name;  // "spots", "fields", "focal-shift"
    std::string caption;
    std::vector<std::string> columns;
    std::vector<std::vector<ShownValue>> rows;
};

// Spot radii and fans are shown in micrometres, the sizes designers read: micrometres per mm.
inline constexpr double kUm = 1000;

// What every view shows for a field no ray of which reaches the image plane, in place of its image
// height, distortion and illumination, and (with why) in place of its spot.
inline constexpr const char* kNotImaged = "not imaged";
inline constexpr const char* kNotImagedWhy = "not imaged: no ray reaches the image plane";

// f-number, focus, image plane and its z (and the other planes'), reference point, primary
// wavelength, largest field and its source, central obscuration, the MTF's range.
std::vector<AnalysisSetting> analysisSettings(const LensDesignAnalysis& analysis);

// Spot radii per field and wavelength; image height, distortion and (with `curves`: the analysis
// sampled the curves against field) relative illumination per field; chromatic focal shift.
std::vector<AnalysisTable> analysisTables(const LensDesignAnalysis& analysis, bool curves = true);

// A wavelength's RMS spot radius in micrometres as the tables show it (the spot plot's legend too).
ShownValue spotRmsShown(const LensDesignAnalysis& analysis, std::size_t field, std::size_t wavelength);

// The data-* attributes of a shown value (none for a label).
std::vector<std::pair<std::string, std::string>> shownValueAttributes(const ShownValue& value);

// The settings in one line ("f-number: f/2; focus: infinity; ..."), as the command line prints them.
std::string analysisSettingsText(const LensDesignAnalysis& analysis);
// The settings as a description list, the tables as <table>s, each value marked.
std::string analysisSettingsHtml(const LensDesignAnalysis& analysis);
std::string analysisTablesHtml(const LensDesignAnalysis& analysis, bool curves = true);
// The tables as text: the caption, then columns separated by two spaces.
std::string analysisTablesText(const LensDesignAnalysis& analysis, bool curves = true);

}  // namespace lenslab
