// The SVG plot writer: well-formed markup, escaped text, nice ticks, lines broken at missing values.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <regex>

#include "HtmlCheck.h"
#include "SvgPlot.h"

using namespace lenslab;

namespace {

std::vector<std::string> tickLabels(const std::string& svg, const std::string& anchor) {
    std::vector<std::string> labels;
    const std::regex text("text-anchor=\"" + anchor + "\" fill=\"#333\">([^<]*)</text>");
    for (std::sregex_iterator it(svg.begin(), svg.end(), text), end; it != end; ++it) labels.push_back((*it)[1]);
    return labels;
}

}  // namespace

TEST(SvgPlot, WellFormedWithEscapedTextAndNiceLinearTicks) {
    Plot p;
    p.id = "t";
    p.title = "a < b & c";
    p.x.label = "x (mm)";
    p.y.label = "y";
    p.series = {{"one", {0, 1, 2, 3}, {0.0, 0.3, 0.9, 1.7}}, {"two", {0, 3}, {1, 1}}};
    const std::string svg = svgPlot(p);
    const auto check = test::checkHtml(svg);
    EXPECT_TRUE(check.errors.empty()) << check.errors.front();
    EXPECT_NE(svg.find("a &lt; b &amp; c"), std::string::npos);
    EXPECT_EQ(tickLabels(svg, "middle"), (std::vector<std::string>{"0.0", "0.5", "1.0", "1.5", "2.0", "2.5", "3.0"}));
    EXPECT_EQ(tickLabels(svg, "end"),
              (std::vector<std::string>{"0.00", "0.25", "0.50", "0.75", "1.00", "1.25", "1.50", "1.75"}));
}

TEST(SvgPlot, LogAxesTickDecadesAndSkipNonPositiveValues) {
    Plot p;
    p.id = "log";
    p.x.logarithmic = p.y.logarithmic = true;
    p.series = {{"s", {0.0, 0.02, 3.0}, {5.0, 40.0, 0.7}}};
    const std::string svg = svgPlot(p);
    EXPECT_EQ(tickLabels(svg, "middle"), (std::vector<std::string>{"0.01", "0.1", "1", "10"}));
    EXPECT_EQ(tickLabels(svg, "end"), (std::vector<std::string>{"0.1", "1", "10", "100"}));
}

TEST(SvgPlot, MissingValuesBreakTheLine) {
    Plot p;
    p.id = "gap";
    p.series = {{"s", {0, 1, 2, 3, 4}, {1, 2, std::nan(""), 2, 1}}};
    const std::string svg = svgPlot(p);
    const std::smatch m = [&] {
        std::smatch r;
        std::regex_search(svg, r, std::regex("<path d=\"([^\"]*)\""));
        return r;
    }();
    ASSERT_FALSE(m.empty());
    const std::string d = m[1];
    EXPECT_EQ(std::count(d.begin(), d.end(), 'M'), 2);
    EXPECT_EQ(std::count(d.begin(), d.end(), 'L'), 2);
}

// Tick labels along x never touch, however many decimals a narrow plot's range needs.
TEST(SvgPlot, XTickLabelsNeverTouch) {
    Plot p;
    p.id = "narrow";
    p.width = 240;  // 162 px of axis: six labels like "-0.002" at 0.001 apart would overlap
    p.series = {{"s", {-0.0012, 0.0031}, {0, 1}}};
    const std::string svg = svgPlot(p);
    const std::regex tick("<text x=\"([\\d.]+)\" y=\"[\\d.]+\" text-anchor=\"middle\" fill=\"#333\">([^<]*)</text>");
    std::vector<std::pair<double, std::string>> ticks;
    for (std::sregex_iterator it(svg.begin(), svg.end(), tick), end; it != end; ++it) ticks.emplace_back(std::stod((*it)[1]), (*it)[2]);
    ASSERT_GE(ticks.size(), 3u);
    for (std::size_t i = 1; i < ticks.size(); ++i)
        EXPECT_GE(ticks[i].first - ticks[i - 1].first, 7.2 * 0.5 * (ticks[i].second.size() + ticks[i - 1].second.size()))
            << ticks[i - 1].second << " and " << ticks[i].second;
}
