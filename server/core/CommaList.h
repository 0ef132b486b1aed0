#pragma once
// Comma-separated lists as operators and clients write them ("a, b", "gzip;q=0, deflate"): the
// entries with the spaces and tabs around them removed, empty ones left out.
#include <sstream>
#include <string>
#include <vector>

namespace lenslab {

inline std::string trimmedText(const std::string& text) {
    const std::size_t first = text.find_first_not_of(" \t");
    return first == std::string::npos ? "" : text.substr(first, text.find_last_not_of(" \t") - first + 1);
}

inline std::vector<std::string> commaListEntries(const std::string& list) {
    std::vector<std::string> entries;
    std::stringstream in(list);
    for (std::string entry; std::getline(in, entry, ',');)
        if (!trimmedText(entry).empty()) entries.push_back(trimmedText(entry));
    return entries;
}

}  // namespace lenslab
