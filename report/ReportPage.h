#pragma once
// The report as HTML: one self-contained page (index.html) with a local style sheet, relative
// links to its images and inline SVG plots; no script, no external resource.
#include <string>

#include "ReportContent.h"

namespace lenslab {

std::string reportHtml(const ReportContent& content);
std::string reportStyleSheet();  // style.css

// The section on the algorithms, for a reader who knows the course material.
std::string algorithmsSectionHtml();

}  // namespace lenslab
