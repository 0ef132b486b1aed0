// Builds the quick report with the real `lenslab report` binary and checks the site: every lens and
// scene present, the slanted-edge comparisons within their tolerance, every image a valid PNG of its
// stated size, every link relative and resolving, the tables equal to `lenslab lens --json`, the HTML
// well formed, and a second build reusing everything.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <limits>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <regex>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include "HtmlCheck.h"
#include "PngCodec.h"

namespace fs = std::filesystem;
using lenslab::test::checkHtml;
using lenslab::test::HtmlCheck;

namespace {

const std::vector<std::string> kCommonScale = {"dgauss.50mm", "wide.22mm", "telephoto.250mm", "fisheye.10mm"};

struct CommandRun {
    int status = -1;
    std::string out;
    double seconds = 0;
};

CommandRun run(const std::string& command) {
    CommandRun r;
    const auto start = std::chrono::steady_clock::now();
    FILE* pipe = popen((command + " 2>&1").c_str(), "r");
    if (!pipe) return r;
    char buffer[4096];
    for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0;) r.out.append(buffer, n);
    const int status = pclose(pipe);
    r.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return r;
}

std::string readFile(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

std::vector<std::string> stems(const fs::path& dir, const std::string& extension) {
    std::vector<std::string> ids;
    for (const auto& e : fs::directory_iterator(dir))
        if (e.path().extension() == extension) ids.push_back(e.path().stem().string());
    return ids;
}

// The bundled lens file of an id: its table, else its Zemax file.
fs::path lensFile(const fs::path& source, const std::string& id) {
    const fs::path table = source / "lenses" / (id + ".dat");
    return fs::exists(table) ? table : source / "lenses" / (id + ".zmx");
}

// The bundled lenses: tables and Zemax files.
std::vector<std::string> bundledLenses(const fs::path& source) {
    std::vector<std::string> ids = stems(source / "lenses", ".dat");
    for (const std::string& id : stems(source / "lenses", ".zmx")) ids.push_back(id);
    return ids;
}

// The numbers `report: ... N built, M reused; K renders` from the command's summary line.
struct Counts {
    int built = -1, reused = -1, renders = -1;
};

Counts counts(const std::string& out) {
    std::smatch m;
    Counts c;
    if (std::regex_search(out, m, std::regex(R"((\d+) built, (\d+) reused; (\d+) renders)")))
        c = {std::stoi(m[1]), std::stoi(m[2]), std::stoi(m[3])};
    return c;
}

// What `lenslab COMMAND LENS --focus FOCUS --json` prints (the focus written to the last digit);
// null, with a test failure, when it fails.
nlohmann::json commandJson(const std::string& command, const fs::path& lens, double focus) {
    std::ostringstream focusText;
    focusText.precision(17);
    focusText << focus;
    const CommandRun cli =
        run(std::string(LENSLAB_BINARY) + " " + command + " " + lens.string() + " --focus " + focusText.str() + " --json");
    if (cli.status != 0) {
        ADD_FAILURE() << cli.out;
        return nullptr;
    }
    return nlohmann::json::parse(cli.out);
}

class ReportPage : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        site_ = fs::temp_directory_path() / ("lenslab-report-test-" + std::to_string(getpid()));
        fs::remove_all(site_);
        first_ = run(std::string(LENSLAB_BINARY) + " report --quick --quiet -o " + site_.string());
        html_ = readFile(site_ / "index.html");
    }
    static void TearDownTestSuite() { fs::remove_all(site_); }

    static fs::path site_;
    static CommandRun first_;
    static std::string html_;
};

fs::path ReportPage::site_;
CommandRun ReportPage::first_;
std::string ReportPage::html_;

TEST_F(ReportPage, BuildsQuicklyAndWellFormed) {
    ASSERT_EQ(first_.status, 0) << first_.out;
    const Counts c = counts(first_.out);
    EXPECT_GT(c.built, 0) << first_.out;
    EXPECT_EQ(c.reused, 0);
    const HtmlCheck check = checkHtml(html_);
    for (const std::string& e : check.errors) ADD_FAILURE() << e;
    EXPECT_EQ(html_.rfind("<!DOCTYPE html>", 0), 0u);
}

TEST_F(ReportPage, EveryLensAndSceneAppears) {
    ASSERT_EQ(first_.status, 0) << first_.out;
    const fs::path source = LENSLAB_SOURCE_DIR;
    for (const std::string& lens : bundledLenses(source)) {
        EXPECT_NE(html_.find("id=\"lens-" + lens + "\""), std::string::npos) << lens;
        for (const char* mode : {"exact", "thick", "overlay"})
            EXPECT_NE(html_.find("src=\"assets/lenses/" + lens + "-" + mode + ".png\""), std::string::npos) << lens << " " << mode;
    }
    const auto scenes = stems(source / "scenes", ".pbrt");
    ASSERT_FALSE(scenes.empty());
    for (const std::string& scene : scenes) {
        EXPECT_NE(html_.find("id=\"scene-" + scene + "\""), std::string::npos) << scene;
        for (const std::string& lens : kCommonScale)
            for (const char* kind : {"exact", "thick", "difference"})
                EXPECT_NE(html_.find("src=\"assets/renders/" + scene + "/" + lens + "-" + kind + ".png\""), std::string::npos)
                    << scene << " " << lens << " " << kind;
    }
    // Inline SVG plots: per lens the thick-lens error, and illumination and distortion only where the
    // designer's analysis draws none (a lens without a largest field), plus the three comparisons.
    std::size_t plots = 0, expected = 3;
    for (std::size_t at = html_.find("<svg"); at != std::string::npos; at = html_.find("<svg", at + 1)) ++plots;
    for (const std::string& lens : bundledLenses(source)) {
        SCOPED_TRACE(lens);
        const nlohmann::json analysis = nlohmann::json::parse(readFile(site_ / "assets/lenses" / (lens + "-analysis/analysis.json")));
        const bool curves = !analysis["largest_field_deg"].is_null();
        expected += curves ? 1 : 3;
        const std::size_t begin = html_.find("<article class=\"lens\" id=\"lens-" + lens + "\">");
        ASSERT_NE(begin, std::string::npos);
        const std::string article = html_.substr(begin, html_.find("</article>", begin) - begin);
        for (const std::string panel : {"illumination-", "distortion-"})
            EXPECT_EQ(article.find("<title id=\"" + panel + lens + "-title\">") == std::string::npos, curves) << panel;
        EXPECT_EQ(article.find("distortion.svg\"") != std::string::npos, curves);
    }
    EXPECT_EQ(plots, expected);
}

TEST_F(ReportPage, TheRenderAgreesWithTheAnalysisThroughTheSlantedEdges) {
    ASSERT_EQ(first_.status, 0) << first_.out;
    for (const char* edge : {"dgauss.50mm-0-tangential", "dgauss.50mm-8-tangential", "dgauss.50mm-8-sagittal",
                             "wide.22mm-0-tangential", "wide.22mm-15-tangential", "wide.22mm-15-sagittal"})
        EXPECT_NE(html_.find(std::string("src=\"assets/slanted-edge/") + edge + ".svg\""), std::string::npos) << edge;
    const std::regex difference("half Nyquist is ([0-9.]+)\\.</figcaption>");
    int captions = 0;
    for (auto it = std::sregex_iterator(html_.begin(), html_.end(), difference); it != std::sregex_iterator(); ++it, ++captions)
        EXPECT_LE(std::stod((*it)[1]), 0.05) << it->str();
    EXPECT_EQ(captions, 6);
}

TEST_F(ReportPage, EveryImageIsAValidPngOfItsStatedSizeAndEveryLinkIsLocal) {
    ASSERT_EQ(first_.status, 0) << first_.out;
    const HtmlCheck check = checkHtml(html_);
    std::set<std::string> ids;
    for (const auto& e : check.elements)
        if (e.attributes.count("id")) ids.insert(e.attributes.at("id"));
    int images = 0;
    for (const auto& e : check.elements) {
        for (const char* attribute : {"src", "href"}) {
            if (!e.attributes.count(attribute)) continue;
            const std::string link = e.attributes.at(attribute);
            SCOPED_TRACE(link);
            EXPECT_EQ(link.find("://"), std::string::npos);
            EXPECT_NE(link.rfind("/", 0), 0u) << "absolute path";
            if (link == "data:,") continue;  // the empty favicon
            if (link[0] == '#') {
                EXPECT_TRUE(ids.count(link.substr(1))) << "no element with that id";
                continue;
            }
            EXPECT_TRUE(fs::is_regular_file(site_ / link));
        }
        if (e.name != "img") continue;
        ++images;
        const std::string src = e.attributes.at("src");
        const std::string bytes = readFile(site_ / src);
        EXPECT_FALSE(e.attributes.at("alt").empty()) << src;
        if (fs::path(src).extension() == ".svg") {
            // A standalone SVG file: the namespace (else browsers show nothing) and well-formed markup.
            EXPECT_EQ(bytes.rfind("<svg xmlns=\"http://www.w3.org/2000/svg\"", 0), 0u) << src;
            for (const std::string& error : checkHtml(bytes).errors) ADD_FAILURE() << src << ": " << error;
            continue;
        }
        try {
            const lenslab::RgbaImage png = lenslab::decodePng(std::vector<std::uint8_t>(bytes.begin(), bytes.end()));
            EXPECT_EQ(std::to_string(png.width), e.attributes.at("width")) << src;
            EXPECT_EQ(std::to_string(png.height), e.attributes.at("height")) << src;
        } catch (const std::exception& x) {
            ADD_FAILURE() << src << ": " << x.what();
        }
    }
    EXPECT_GT(images, 24);
    // The SVG namespace is a name, not an address anything is fetched from.
    const std::regex svgNamespace(R"re(xmlns="http://www\.w3\.org/2000/svg")re");
    for (const std::string& text : {std::regex_replace(html_, svgNamespace, ""), readFile(site_ / "style.css")}) {
        EXPECT_EQ(text.find("http://"), std::string::npos);
        EXPECT_EQ(text.find("https://"), std::string::npos);
        EXPECT_EQ(text.find("url("), text.find("url(#")) << "a stylesheet or SVG fetch";
    }
}

TEST_F(ReportPage, TablesHoldTheNumbersOfLensJson) {
    ASSERT_EQ(first_.status, 0) << first_.out;
    const fs::path source = LENSLAB_SOURCE_DIR;
    const std::regex cell(R"re(<td data-key="([^"]+)">([^<]*)</td>)re");
    for (const std::string& lens : bundledLenses(source)) {
        SCOPED_TRACE(lens);
        // At the report's focus: 2 m, or 20 focal lengths for a lens that cannot focus so close.
        const nlohmann::json stored = nlohmann::json::parse(readFile(site_ / "assets/lenses" / (lens + ".json")));
        const double focus = stored["focus"]["distance"].get<double>();
        EXPECT_TRUE(focus == 2000 || std::fabs(focus - 20 * stored["efl"].get<double>()) < 1e-9) << focus;
        nlohmann::json expected = commandJson("lens", lensFile(source, lens), focus);
        expected["name"] = lensFile(source, lens).filename().string();  // published: not where it lies
        EXPECT_EQ(stored, expected);

        const std::size_t begin = html_.find("<article class=\"lens\" id=\"lens-" + lens + "\">");
        ASSERT_NE(begin, std::string::npos);
        const std::string article = html_.substr(begin, html_.find("</article>", begin) - begin);
        int cells = 0;
        for (std::sregex_iterator it(article.begin(), article.end(), cell), end; it != end; ++it, ++cells) {
            const std::string key = (*it)[1], text = (*it)[2];
            nlohmann::json node = expected;
            std::istringstream path(key);
            for (std::string part; std::getline(path, part, '.');) node = node.at(part);
            if (node.is_null()) {  // a number the lens does not define (a field it does not limit)
                EXPECT_EQ(text, "none") << key;
                continue;
            }
            const std::size_t dot = text.find('.');
            const int decimals = dot == std::string::npos ? 0 : static_cast<int>(text.size() - dot - 1);
            EXPECT_NEAR(std::stod(text), node.get<double>(), 0.5 * std::pow(10.0, -decimals) + 1e-12) << key;
        }
        EXPECT_GE(cells, 20);
        // The image circle: a number where rays stop within the search (2 EFL + 50 mm), else none (the
        // doublet with its stop at the glass passes rays at every angle).
        std::smatch circle;
        ASSERT_TRUE(std::regex_search(article, circle, std::regex("<th scope=\"row\">Image circle radius</th><td>([^<]*)</td>")));
        if (lens == "ac254-100-a") {
            EXPECT_EQ(circle[1], "none");
        } else if (lens == "dgauss.50mm") {
            EXPECT_GT(std::stod(circle[1]), 0);
            EXPECT_LT(std::stod(circle[1]), 2 * std::fabs(expected["efl"].get<double>()) + 50);
        }
    }
}

// Each lens's designer's analysis: the 13 plots (spot, MTF, fans at three fields; four curves) and
// the data that `lenslab analyze --json` prints for the same lens at its widest, focused at infinity
// (as the web page first analyses it; the tables' focus is the report's 2 m).
TEST_F(ReportPage, EveryLensShowsTheDesignersAnalysisOfTheCommandLine) {
    ASSERT_EQ(first_.status, 0) << first_.out;
    const fs::path source = LENSLAB_SOURCE_DIR;
    for (const std::string& lens : bundledLenses(source)) {
        SCOPED_TRACE(lens);
        const std::size_t begin = html_.find("<article class=\"lens\" id=\"lens-" + lens + "\">");
        ASSERT_NE(begin, std::string::npos);
        const std::string article = html_.substr(begin, html_.find("</article>", begin) - begin);
        const std::string folder = "assets/lenses/" + lens + "-analysis/";
        const double focus = std::numeric_limits<double>::infinity();
        EXPECT_NE(article.find(", focused at infinity</h4>"), std::string::npos);
        const nlohmann::json expected = commandJson("analyze", lensFile(source, lens), focus);
        EXPECT_EQ(nlohmann::json::parse(readFile(site_ / (folder + "analysis.json"))), expected);
        // A spot, MTF and fan plot per analysed field (the axis alone for a lens without a largest
        // field), and the four curves where there is a field to draw them over.
        std::vector<std::string> plots;
        const std::size_t fields = expected["fields"].size();
        EXPECT_EQ(fields, expected["largest_field_deg"].is_null() ? 1u : 3u);
        for (const char* kind : {"spot", "mtf", "fans"})
            for (std::size_t field = 1; field <= fields; ++field) plots.push_back(std::string(kind) + "-field-" + std::to_string(field));
        for (const char* curve : {"field-curvature", "distortion", "relative-illumination"})
            if (!expected["largest_field_deg"].is_null()) plots.push_back(curve);
        plots.push_back("chromatic-focal-shift");
        for (const std::string& plot : plots)
            EXPECT_NE(article.find("<img src=\"" + folder + plot + ".svg\""), std::string::npos) << plot;
        // The captions name each field as the data does.
        for (const nlohmann::json& field : expected["fields"]) {
            char degrees[32];
            std::snprintf(degrees, sizeof degrees, "Spot diagram at %.1f\u00b0", field["field_deg"].get<double>());
            EXPECT_NE(article.find(degrees), std::string::npos) << degrees;
        }
        // The ghost analysis: its plot, and a table of its brightest ghosts in the order and count of
        // `lenslab analyze --ghosts --json`.
        EXPECT_NE(article.find("<img src=\"" + folder + "ghosts.svg\""), std::string::npos);
        const nlohmann::json ghosts = commandJson("analyze --ghosts", lensFile(source, lens), focus);
        const std::size_t table = article.find("<table class=\"ghosts\">");
        ASSERT_NE(table, std::string::npos);
        const std::string count = "of " + std::to_string(ghosts["ghosts"].size()) + " ghosts (" +
                                  std::to_string(ghosts["reflecting_surfaces"].get<int>()) + " reflecting surfaces)";
        EXPECT_NE(article.find(count, table), std::string::npos) << count;
        std::size_t at = table;
        for (std::size_t i = 0; i < std::min<std::size_t>(8, ghosts["ghosts"].size()); ++i) {
            const nlohmann::json& surfaces = ghosts["ghosts"][i]["surfaces"];
            const std::string row = "<th scope=\"row\">" + std::to_string(surfaces[0].get<int>()) + "\u2013" +
                                    std::to_string(surfaces[1].get<int>()) + "</th>";
            at = article.find(row, at);
            ASSERT_NE(at, std::string::npos) << "ghost " << i + 1 << ": " << row;
        }
    }
}

TEST_F(ReportPage, SecondBuildReusesEverythingAndRendersNothing) {
    ASSERT_EQ(first_.status, 0) << first_.out;
    const CommandRun second = run(std::string(LENSLAB_BINARY) + " report --quick --quiet -o " + site_.string());
    ASSERT_EQ(second.status, 0) << second.out;
    const Counts before = counts(first_.out), after = counts(second.out);
    EXPECT_EQ(after.built, 0) << second.out;
    EXPECT_EQ(after.renders, 0);
    EXPECT_EQ(after.reused, before.built);
    EXPECT_LT(second.seconds, std::max(2.0, 0.5 * first_.seconds));
}

TEST_F(ReportPage, ChromiumShowsThePageWithEveryImage) {
    ASSERT_EQ(first_.status, 0) << first_.out;
    const fs::path browser = fs::path(LENSLAB_SOURCE_DIR) / "tests/browser";
    if (!fs::exists(browser / "node_modules/playwright-core") || run("command -v node").status != 0)
        GTEST_SKIP() << "needs node and playwright-core in tests/browser/node_modules (npm ci there)";
    const fs::path shot = site_.string() + "-screenshot.png";
    const CommandRun r = run("node " + (browser / "report-screenshot.cjs").string() + " " + site_.string() + " " + shot.string());
    ASSERT_EQ(r.status, 0) << r.out;
    const std::string bytes = readFile(shot);
    const lenslab::RgbaImage png = lenslab::decodePng(std::vector<std::uint8_t>(bytes.begin(), bytes.end()));
    EXPECT_EQ(png.width, 1280);
    fs::remove(shot);
}

}  // namespace
