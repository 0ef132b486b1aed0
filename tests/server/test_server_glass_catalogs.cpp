// Zemax glass catalogs uploaded to the real `lenslab serve` (POST /api/glass-catalogs): listed and
// shown glass by glass, their glasses read by lenses uploaded afterwards (the singlet's EFL against
// the thick-lens lensmaker's formula with the index from the Sellmeier terms, computed here),
// refused with the reader's line, bounded, deleted only when no lens uses them, kept over a restart,
// never changing a glass the bundled makers have, and taken 40 at once while health answers.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <future>
#include <tuple>
#include <vector>

#include "ServerProcess.h"

using namespace lenslab::test;
using nlohmann::json;

namespace {

// One Sellmeier 1 glass (Zemax formula 2: K1 L1 K2 L2 K3 L3, L in micrometres) of our own numbers.
constexpr double kB[3] = {1.2, 0.25, 1.0}, kC[3] = {0.008, 0.03, 95.0};
const std::string kCatalog =
    "CC lenslab test catalog\n"
    "NM LLAB-SELL1 2 0 1.5807 47.11 0 0 0\n"
    "GC a glass of the test's own numbers\n"
    "ED 7.1 0 2.5 0 0\n"
    "CD 1.2 0.008 0.25 0.03 1.0 95.0 0 0 0 0\n"
    "TD 0 0 0 0 0 0 20\n"
    "LD 0.3 2.5\n";

double sellmeierIndex(double nm, double b1 = kB[0]) {
    const double l2 = (nm / 1000) * (nm / 1000);
    double n2 = 1;
    for (int i = 0; i < 3; ++i) n2 += (i == 0 ? b1 : kB[i]) * l2 / (l2 - kC[i]);
    return std::sqrt(n2);
}
const double kNd = sellmeierIndex(587.5618);

// R1 50, thickness 5, R2 -50 in the test glass, then the stop: gap-after rows.
const std::string kSingletInTestGlass =
    "50.0 5.0 1.5807 20.0 LLAB-SELL1\n-50.0 10.0 1.0 20.0\n0.0 0.0 0.0 15.0\n";

// The lensmaker's formula for a thick lens in air: 1/f = (n-1) [1/R1 - 1/R2 + (n-1) t / (n R1 R2)].
double thickLensEfl(double n, double r1, double r2, double t) {
    return 1 / ((n - 1) * (1 / r1 - 1 / r2 + (n - 1) * t / (n * r1 * r2)));
}

Reply postCatalog(httplib::Client& c, const std::string& name, const std::string& text) {
    return postRaw(c, "/api/glass-catalogs?name=" + name, text);
}

class ServerGlassCatalogs : public ::testing::Test {
protected:
    void SetUp() override { start(); }
    void start() { server_ = std::make_unique<ServerProcess>(binaryUnderTest(), dataDir()); }
    void restart() {
        server_.reset();
        start();
    }
    std::string dataDir() const { return data_.path() + "/data"; }
    std::size_t storedFiles() const {
        std::size_t n = 0;
        for (const auto& f : std::filesystem::directory_iterator(dataDir() + "/glass-catalogs")) n += f.is_regular_file();
        return n;
    }
    TempDir data_;
    std::unique_ptr<ServerProcess> server_;
};

bool listsGlass(httplib::Client& c, const std::string& name) {
    const Reply glasses = get(c, "/api/glasses");
    for (const json& g : glasses.body.at("glasses"))
        if (g["name"] == name) return true;
    return false;
}

}  // namespace

TEST_F(ServerGlassCatalogs, ALensNamingTheCatalogsGlassReadsOnlyAfterTheUpload) {
    auto c = server_->client();
    const Reply before = postRaw(c, "/api/lenses?name=singlet.dat", kSingletInTestGlass);
    EXPECT_EQ(before.status, 400) << before.raw;
    EXPECT_EQ(before.body["line"], 1);
    EXPECT_NE(before.body["problem"].get<std::string>().find("unknown glass 'LLAB-SELL1'"), std::string::npos) << before.raw;
    EXPECT_FALSE(listsGlass(c, "LLAB-SELL1"));

    const Reply up = postCatalog(c, "llab.agf", kCatalog);
    ASSERT_EQ(up.status, 201) << up.raw;
    EXPECT_EQ(up.body["name"], "LLAB");
    EXPECT_EQ(up.body["file_name"], "llab.agf");
    EXPECT_EQ(up.body["glass_count"], 1);
    EXPECT_EQ(up.body["formulas"], json::array({2}));
    EXPECT_EQ(up.body["shadowed_count"], 0);
    const std::string id = up.body["id"];
    EXPECT_EQ(up.header("Location"), "/api/glass-catalogs/" + id);

    const Reply list = get(c, "/api/glass-catalogs");
    ASSERT_EQ(list.body["catalogs"].size(), 1u) << list.raw;
    EXPECT_EQ(list.body["catalogs"][0]["id"], id);
    const Reply shown = get(c, "/api/glass-catalogs/" + id);
    ASSERT_EQ(shown.status, 200) << shown.raw;
    const json glass = shown.body["glasses"][0];
    EXPECT_EQ(glass["name"], "LLAB-SELL1");
    EXPECT_EQ(glass["formula"], 2);
    EXPECT_DOUBLE_EQ(glass["nd"].get<double>(), 1.5807);
    EXPECT_DOUBLE_EQ(glass["vd"].get<double>(), 47.11);
    EXPECT_NEAR(glass["nd_formula"].get<double>(), kNd, 1e-12);
    const double vd = (kNd - 1) / (sellmeierIndex(486.1327) - sellmeierIndex(656.2725));
    EXPECT_NEAR(glass["vd_formula"].get<double>(), vd, 1e-9);
    EXPECT_DOUBLE_EQ(glass["min_nm"].get<double>(), 300);
    EXPECT_TRUE(listsGlass(c, "LLAB-SELL1"));

    const Reply lens = postRaw(c, "/api/lenses?name=singlet.dat", kSingletInTestGlass);
    ASSERT_EQ(lens.status, 201) << lens.raw;
    EXPECT_NEAR(lens.body["efl"].get<double>(), thickLensEfl(kNd, 50, -50, 5), 1e-9);
}

TEST_F(ServerGlassCatalogs, AMalformedCatalogIs422WithTheLineAndNothingIsStored) {
    auto c = server_->client();
    const Reply r = postCatalog(c, "bad.agf", "CC fine\nNM G1 2 0 1.5 60 0 0 0\nCD 1.0 0.01 five 0 0 0\n");
    EXPECT_EQ(r.status, 422) << r.raw;
    EXPECT_EQ(r.body["line"], 3);
    EXPECT_EQ(r.body["file"], "bad.agf");
    EXPECT_EQ(r.body["problem"], "a CD coefficient is not a finite number: 'five'");
    EXPECT_EQ(r.body["error"], "bad.agf:3: a CD coefficient is not a finite number: 'five'");
    const Reply garbage = postCatalog(c, "x.agf", std::string("\x00\x01\x02 not a catalog \xff", 20));
    EXPECT_EQ(garbage.status, 422) << garbage.raw;
    EXPECT_EQ(postCatalog(c, "x.agf", " \n\t").status, 400);
    EXPECT_EQ(get(c, "/api/glass-catalogs").body["catalogs"].size(), 0u);
    EXPECT_EQ(storedFiles(), 0u);
}

// Issue 40, item 9: a glass name is at most 64 characters (a megabyte was taken), and one name twice
// in a catalog is refused at its second NM line (a lens could find only the first).
TEST_F(ServerGlassCatalogs, OverlongAndRepeatedGlassNamesAre422WithTheirLine) {
    auto c = server_->client();
    const std::string glass = "NM %s 2 0 1.5807 47.11 0 0 0\nCD 1.2 0.008 0.25 0.03 1.0 95.0 0 0 0 0\n";
    const auto nm = [&](const std::string& name) { return glass.substr(0, 3) + name + glass.substr(5); };
    const Reply overlong = postCatalog(c, "long.agf", nm("G1") + nm(std::string(65, 'G')));
    EXPECT_EQ(overlong.status, 422) << overlong.raw;
    EXPECT_EQ(overlong.body["error"], "long.agf:3: the glass name has 65 characters, more than 64");
    EXPECT_EQ(postCatalog(c, "longest.agf", nm(std::string(64, 'G'))).status, 201);
    const Reply twice = postCatalog(c, "twice.agf", "CC two of one name\n" + nm("G1") + nm("G2") + nm("g1"));
    EXPECT_EQ(twice.status, 422) << twice.raw;
    EXPECT_EQ(twice.body["line"], 6);
    EXPECT_EQ(twice.body["error"], "twice.agf:6: glass g1 is named twice in the catalog: first on line 2; a lens could find only one of them");
    EXPECT_EQ(get(c, "/api/glass-catalogs").body["catalogs"].size(), 1u);
}

// Issue 40, item 9: a catalog name that could pass for another (fullwidth letters, a zero-width
// space after SCHOTT) is refused with 400 before the file is read.
TEST_F(ServerGlassCatalogs, CatalogNamesOtherThanPrintableAsciiAre400) {
    auto c = server_->client();
    for (const std::string name : {"\xef\xbc\xb3\xef\xbc\xa3\xef\xbc\xa8\xef\xbc\xaf\xef\xbc\xb4\xef\xbc\xb4.agf",
                                   "SCHOTT\xe2\x80\x8b.agf"}) {
        const auto r = c.Post("/api/glass-catalogs", httplib::MultipartFormDataItems{{"file", kCatalog, name, "text/plain"}});
        ASSERT_TRUE(r);
        EXPECT_EQ(r->status, 400) << r->body;
        const json body = json::parse(r->body, nullptr, false);
        EXPECT_EQ(body["error"], "the glass catalog's file name '" + name +
                                     "' has characters other than printable ASCII (letters, digits, punctuation, spaces): "
                                     "its name could pass for another catalog's");
    }
    EXPECT_EQ(get(c, "/api/glass-catalogs").body["catalogs"].size(), 0u);
    EXPECT_EQ(storedFiles(), 0u);
}

// Issue 40, item 9: a deletion killed between the file and its record left a record that every
// start skipped with a message; the next start removes it, once.
TEST_F(ServerGlassCatalogs, ARecordWhoseFileIsGoneIsRemovedAtTheNextStartOnce) {
    auto c = server_->client();
    const std::string id = postCatalog(c, "llab.agf", kCatalog).body["id"];
    server_.reset();
    std::filesystem::remove(dataDir() + "/glass-catalogs/" + id + ".agf");
    start();
    EXPECT_NE(server_->output().find("removed the record of glass catalog " + id + ", whose file is gone"), std::string::npos)
        << server_->output();
    auto after = server_->client();
    EXPECT_EQ(get(after, "/api/glass-catalogs").body["catalogs"].size(), 0u);
    EXPECT_EQ(postCatalog(after, "llab.agf", kCatalog).status, 201);  // its name is free again
    restart();
    EXPECT_EQ(server_->output().find(id), std::string::npos) << server_->output();
}

TEST_F(ServerGlassCatalogs, ACatalogPastTheBodyLimitIs413) {
    auto c = server_->client();
    std::string huge = kCatalog;
    while (huge.size() <= (1u << 20)) huge += "CC " + std::string(1000, 'x') + "\n";
    const Reply r = postCatalog(c, "huge.agf", huge);
    EXPECT_EQ(r.status, 413) << r.raw.substr(0, 200);
    EXPECT_EQ(get(c, "/api/glass-catalogs").body["catalogs"].size(), 0u);
    EXPECT_EQ(storedFiles(), 0u);
}

TEST_F(ServerGlassCatalogs, ACatalogThatALensUsesIsNotDeleted) {
    auto c = server_->client();
    const std::string catalog = postCatalog(c, "llab.agf", kCatalog).body["id"];
    const Reply lens = postRaw(c, "/api/lenses?name=singlet.dat", kSingletInTestGlass);
    ASSERT_EQ(lens.status, 201) << lens.raw;
    const std::string lensId = lens.body["id"];

    const Reply refused = remove(c, "/api/glass-catalogs/" + catalog);
    EXPECT_EQ(refused.status, 409) << refused.raw;
    EXPECT_NE(refused.body["error"].get<std::string>().find(lensId), std::string::npos) << refused.raw;
    EXPECT_EQ(get(c, "/api/glass-catalogs").body["catalogs"].size(), 1u);

    EXPECT_EQ(remove(c, "/api/lenses/" + lensId).status, 200);
    const Reply deleted = remove(c, "/api/glass-catalogs/" + catalog);
    EXPECT_EQ(deleted.status, 200) << deleted.raw;
    EXPECT_EQ(deleted.body["deleted"], catalog);
    EXPECT_EQ(get(c, "/api/glass-catalogs").body["catalogs"].size(), 0u);
    EXPECT_EQ(get(c, "/api/glass-catalogs/" + catalog).status, 404);
    EXPECT_EQ(remove(c, "/api/glass-catalogs/" + catalog).status, 404);
    EXPECT_EQ(storedFiles(), 0u);
    EXPECT_FALSE(listsGlass(c, "LLAB-SELL1"));
    EXPECT_EQ(postRaw(c, "/api/lenses?name=singlet.dat", kSingletInTestGlass).status, 400);
}

TEST_F(ServerGlassCatalogs, CatalogsAndTheLensesUsingThemSurviveARestart) {
    auto c = server_->client();
    const std::string catalog = postCatalog(c, "llab.agf", kCatalog).body["id"];
    const std::string lens = postRaw(c, "/api/lenses?name=singlet.dat", kSingletInTestGlass).body["id"];
    restart();
    auto after = server_->client();
    const Reply list = get(after, "/api/glass-catalogs");
    ASSERT_EQ(list.body["catalogs"].size(), 1u) << list.raw;
    EXPECT_EQ(list.body["catalogs"][0]["id"], catalog);
    EXPECT_EQ(list.body["catalogs"][0]["name"], "LLAB");
    const Reply stored = get(after, "/api/lenses/" + lens);
    ASSERT_EQ(stored.status, 200) << stored.raw << server_->output();
    EXPECT_NEAR(stored.body["efl"].get<double>(), thickLensEfl(kNd, 50, -50, 5), 1e-9);
    EXPECT_EQ(postRaw(after, "/api/lenses?name=again.dat", kSingletInTestGlass).status, 201);
    EXPECT_EQ(remove(after, "/api/glass-catalogs/" + catalog).status, 409);
}

// Issue 40, finding 5: analyses were cached by the lens's text alone, so the same table uploaded
// again after its catalog was replaced (deleted, uploaded under its name with another glass) was
// answered with the old glass's analysis. The cache keys hold the catalogs' digest now.
TEST_F(ServerGlassCatalogs, AReplacedCatalogIsNotAnsweredFromTheOldGlasssCache) {
    auto c = server_->client();
    const auto uploadAndAnalyse = [&](const std::string& catalogText) {
        const Reply catalog = postCatalog(c, "llab.agf", catalogText);
        EXPECT_EQ(catalog.status, 201) << catalog.raw;
        const Reply lens = postRaw(c, "/api/lenses?name=singlet.dat", kSingletInTestGlass);
        EXPECT_EQ(lens.status, 201) << lens.raw;
        const std::string id = lens.body["id"];
        const std::string query = "?fstop=8&focus=inf&wavelengths=d&fields=0";
        const Reply analysis = get(c, "/api/lenses/" + id + "/analysis" + query);
        EXPECT_EQ(analysis.status, 200) << analysis.raw.substr(0, 300);
        EXPECT_EQ(analysis.body["efl"], lens.body["efl"]);
        const Reply ghosts = get(c, "/api/lenses/" + id + "/ghosts?fstop=8&focus=inf");
        EXPECT_EQ(ghosts.status, 200) << ghosts.raw.substr(0, 300);
        EXPECT_EQ(remove(c, "/api/lenses/" + id).status, 200);
        EXPECT_EQ(remove(c, "/api/glass-catalogs/" + catalog.body["id"].get<std::string>()).status, 200);
        json ghostsOfTheGlass = ghosts.body;
        ghostsOfTheGlass.erase("id");  // a new upload's
        return std::make_tuple(lens.body["efl"].get<double>(), analysis.body["image_z"].get<double>(), ghostsOfTheGlass);
    };
    const auto [eflBefore, imageZBefore, ghostsBefore] = uploadAndAnalyse(kCatalog);
    EXPECT_NEAR(eflBefore, thickLensEfl(kNd, 50, -50, 5), 1e-9);
    // The first Sellmeier term 1.2 -> 1.6: nd about 1.70 instead of 1.58.
    std::string denser = kCatalog;
    denser.replace(denser.find("CD 1.2 "), 7, "CD 1.6 ");
    const auto [eflAfter, imageZAfter, ghostsAfter] = uploadAndAnalyse(denser);
    EXPECT_NEAR(eflAfter, thickLensEfl(sellmeierIndex(587.5618, 1.6), 50, -50, 5), 1e-9);  // 36.2 against 43.9
    EXPECT_GT(imageZAfter, imageZBefore + 5);  // the shorter focal length's image nearer the lens
    EXPECT_NE(ghostsAfter, ghostsBefore);
}

// An upload adds glass names: one the bundled makers have keeps the makers' glass (and says so).
TEST_F(ServerGlassCatalogs, AnUploadNeverChangesABundledGlass) {
    auto c = server_->client();
    const std::string lens = "50.0 5.0 1.5168 20.0 N-BK7\n-50.0 10.0 1.0 20.0\n0.0 0.0 0.0 15.0\n";
    const double efl = postRaw(c, "/api/lenses?name=bk7.dat", lens).body["efl"];
    const Reply up = postCatalog(c, "fake.agf", "NM N-BK7 2 0 1.9 30 0 0 0\nCD 2.0 0.01 0 0 0 0\n");
    ASSERT_EQ(up.status, 201) << up.raw;
    EXPECT_EQ(up.body["shadowed_count"], 1);
    EXPECT_EQ(get(c, "/api/glass-catalogs/" + up.body["id"].get<std::string>()).body["glasses"][0]["shadowed"], true);
    const Reply again = postRaw(c, "/api/lenses?name=bk7.dat", lens);
    ASSERT_EQ(again.status, 201) << again.raw;
    EXPECT_EQ(again.body["efl"].get<double>(), efl);
    EXPECT_NEAR(efl, thickLensEfl(1.5168, 50, -50, 5), 2e-3);
}

// Names: only the last path component, a safe alphabet; a catalog name taken (a bundled maker's,
// another upload's, spelt differently) is 409.
TEST_F(ServerGlassCatalogs, OddNamesAreCleanedAndTakenNamesRefused) {
    auto c = server_->client();
    const auto odd = c.Post("/api/glass-catalogs",
                            httplib::MultipartFormDataItems{{"file", kCatalog, "../../my \x01<cat>\xe2\x80\xae\xff.agf", "text/plain"}});
    ASSERT_TRUE(odd);
    ASSERT_EQ(odd->status, 201) << odd->body;
    EXPECT_EQ(json::parse(odd->body)["file_name"], "my cat.agf");
    EXPECT_EQ(json::parse(odd->body)["name"], "MY CAT");
    const Reply clash = postCatalog(c, "my-cat.agf", kCatalog);
    EXPECT_EQ(clash.status, 409) << clash.raw;
    EXPECT_NE(clash.raw.find("MY-CAT"), std::string::npos);
    EXPECT_EQ(postCatalog(c, "Schott.agf", kCatalog).status, 409);
    EXPECT_EQ(get(c, "/api/glass-catalogs/.hidden").status, 400);
    EXPECT_EQ(get(c, "/api/glass-catalogs").body["catalogs"].size(), 1u);
}

// 40 uploads at once: each is stored or refused as busy (429), never half; of 40 of one name one is
// stored. Health answers meanwhile.
TEST_F(ServerGlassCatalogs, FortyConcurrentUploads) {
    for (const bool sameName : {false, true}) {
        std::vector<std::future<int>> uploads;
        for (int i = 0; i < 40; ++i)
            uploads.push_back(std::async(std::launch::async, [&, i] {
                auto c = server_->client();
                const std::string name = sameName ? "same.agf" : "c" + std::to_string(i) + ".agf";
                return postCatalog(c, name, kCatalog).status;
            }));
        auto c = server_->client();
        EXPECT_EQ(get(c, "/api/health").status, 200);
        int stored = 0;
        for (auto& u : uploads) {
            const int status = u.get();
            EXPECT_TRUE(status == 201 || status == 429 || (sameName && status == 409)) << status;
            stored += status == 201;
        }
        if (sameName) EXPECT_EQ(stored, 1);
        else EXPECT_GE(stored, 1);
    }
    auto c = server_->client();
    EXPECT_EQ(get(c, "/api/glass-catalogs").body["catalogs"].size(), storedFiles());
}

// Issue 40, finding 4: a large catalog's glass-by-glass answer is built once and shared by readers
// asking at once and after (24 readers of 20,000 glasses took 680 MB building their own).
TEST_F(ServerGlassCatalogs, ConcurrentReadersOfALargeCatalogShareOneAnswer) {
    auto c = server_->client();
    std::string catalog = "CC many glasses\n";
    for (int i = 0; i < 2000; ++i)
        catalog += "NM LLAB-G" + std::to_string(i) + " 2 0 1.5807 47.11 0 0 0\nCD 1.2 0.008 0.25 0.03 1.0 95.0 0 0 0 0\n";
    const Reply up = postCatalog(c, "many.agf", catalog);
    ASSERT_EQ(up.status, 201) << up.raw;
    const std::string path = "/api/glass-catalogs/" + up.body["id"].get<std::string>();
    const auto misses = [&] { return get(c, "/api/health").body["analysis_cache"]["misses"].get<int>(); };
    const int before = misses();
    const ConcurrentReads first = readAtOnce(*server_, path, 8);
    EXPECT_EQ(first.unexpected, 0);
    EXPECT_GE(first.answered, 1);
    const ConcurrentReads again = readAtOnce(*server_, path, 8);
    EXPECT_EQ(again.answered, 8);
    EXPECT_EQ(misses() - before, 1);
    ASSERT_EQ(again.bodies.size(), 1u);
    EXPECT_EQ(first.bodies, again.bodies);
    EXPECT_EQ(json::parse(*again.bodies.begin())["glasses"].size(), 2000u);
}
