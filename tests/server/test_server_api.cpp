// The real `lenslab serve` on a free loopback port, driven over HTTP: health, lenses (bundled,
// uploads good and bad, deletion, restart), diagrams, input checking, and a real render.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <future>
#include <thread>

#include "FileText.h"
#include "RawConnection.h"
#include "ServerProcess.h"

using namespace lenslab::test;
using nlohmann::json;

namespace {

const std::string kBinary = LENSLAB_BINARY;
const std::string kSource = LENSLAB_SOURCE_DIR;

class ServerApi : public ::testing::Test {
protected:
    void SetUp() override { server_ = std::make_unique<ServerProcess>(binaryUnderTest(), data_.path() + "/data"); }
    void restart() {
        server_.reset();
        server_ = std::make_unique<ServerProcess>(binaryUnderTest(), data_.path() + "/data");
    }
    httplib::Client client() { return server_->client(); }

    TempDir data_;
    std::unique_ptr<ServerProcess> server_;
};

Reply uploadMultipart(httplib::Client& c, const std::string& filename, const std::string& content) {
    httplib::MultipartFormDataItems items = {{"file", content, filename, "text/plain"}};
    auto result = c.Post("/api/lenses", items);
    Reply r;
    r.status = result->status;
    r.raw = result->body;
    r.body = json::parse(result->body, nullptr, false);
    return r;
}

}  // namespace

TEST_F(ServerApi, HealthAndVersion) {
    auto c = client();
    const Reply health = get(c, "/api/health");
    ASSERT_EQ(health.status, 200);
    EXPECT_EQ(health.body["status"], "ok");
    EXPECT_FALSE(health.body["version"].get<std::string>().empty());
    const Reply version = get(c, "/api/version");
    ASSERT_EQ(version.status, 200);
    EXPECT_EQ(version.body["version"], health.body["version"]);
    EXPECT_EQ(version.body["api"], 1);
}

TEST_F(ServerApi, ListsBundledLensesByFileName) {
    auto c = client();
    const Reply list = get(c, "/api/lenses");
    ASSERT_EQ(list.status, 200);
    bool found = false;
    for (const json& lens : list.body["lenses"])
        if (lens["id"] == "dgauss.50mm") {
            found = true;
            EXPECT_TRUE(lens["bundled"].get<bool>());
            EXPECT_NEAR(lens["efl"].get<double>(), 50.3578, 1e-3);
        }
    EXPECT_TRUE(found) << list.raw;
}

TEST_F(ServerApi, LensDataMatchesTheCommandLine) {
    auto c = client();
    const Reply api = get(c, "/api/lenses/dgauss.50mm?fstop=4&focus=1000");
    ASSERT_EQ(api.status, 200) << api.raw;
    const std::string command = kBinary + " lens " + kSource + "/lenses/dgauss.50mm.dat --fstop 4 --focus 1000 --json";
    std::string cliText;
    {
        FILE* pipe = popen(command.c_str(), "r");
        ASSERT_NE(pipe, nullptr);
        char buffer[4096];
        while (size_t n = fread(buffer, 1, sizeof buffer, pipe)) cliText.append(buffer, n);
        ASSERT_EQ(pclose(pipe), 0);
    }
    const json cli = json::parse(cliText);
    for (const auto& field : cli.items()) {
        if (field.key() == "name") continue;
        EXPECT_EQ(api.body[field.key()], field.value()) << field.key();
    }
    EXPECT_EQ(api.body["id"], "dgauss.50mm");
    EXPECT_DOUBLE_EQ(api.body["fstop"].get<double>(), 4.0);
    EXPECT_DOUBLE_EQ(api.body["focus"]["distance"].get<double>(), 1000.0);
}

TEST_F(ServerApi, RefusesOutOfRangeLensSettingsInWords) {
    auto c = client();
    const Reply tooWide = get(c, "/api/lenses/dgauss.50mm?fstop=0.9");
    EXPECT_EQ(tooWide.status, 422) << tooWide.raw;
    EXPECT_FALSE(tooWide.body["error"].get<std::string>().empty());
    const Reply notANumber = get(c, "/api/lenses/dgauss.50mm?fstop=abc");
    EXPECT_EQ(notANumber.status, 400);
    EXPECT_NE(notANumber.body["error"].get<std::string>().find("fstop"), std::string::npos);
    // Ranges are optics' one check, and its message names the parameter.
    EXPECT_EQ(tooWide.body["error"].get<std::string>().rfind("query parameter fstop: f-number 0.9", 0), 0u) << tooWide.raw;
    const Reply behind = get(c, "/api/lenses/dgauss.50mm?focus=-5");
    EXPECT_EQ(behind.status, 422);
    EXPECT_EQ(behind.body["error"].get<std::string>().rfind("query parameter focus: ", 0), 0u) << behind.raw;
    EXPECT_EQ(get(c, "/api/lenses/no-such-lens").status, 404);
}

TEST_F(ServerApi, UploadsLensesThatSurviveARestartAndDeletesThem) {
    auto c = client();
    const Reply multipart = uploadMultipart(c, "my wide.dat", readFile(kSource + "/lenses/wide.dat"));
    ASSERT_EQ(multipart.status, 201) << multipart.raw;
    const std::string id = multipart.body["id"];
    EXPECT_EQ(id.rfind("upload-", 0), 0u);
    EXPECT_EQ(multipart.body["name"], "my wide.dat");
    EXPECT_NEAR(multipart.body["efl"].get<double>(), 100.11, 0.05);
    EXPECT_FALSE(multipart.body["bundled"].get<bool>());

    const Reply raw = postRaw(c, "/api/lenses?name=tele.dat", readFile(kSource + "/lenses/telephoto.dat"));
    ASSERT_EQ(raw.status, 201) << raw.raw;
    const std::string rawId = raw.body["id"];

    restart();
    auto after = client();
    const Reply again = get(after, "/api/lenses/" + id);
    ASSERT_EQ(again.status, 200) << again.raw;
    EXPECT_EQ(again.body["efl"], multipart.body["efl"]);
    EXPECT_EQ(get(after, "/api/lenses/" + rawId).status, 200);

    EXPECT_EQ(remove(after, "/api/lenses/" + id).status, 200);
    EXPECT_EQ(get(after, "/api/lenses/" + id).status, 404);
    EXPECT_EQ(remove(after, "/api/lenses/" + id).status, 404);
    const Reply bundled = remove(after, "/api/lenses/dgauss.50mm");
    EXPECT_EQ(bundled.status, 403);
    EXPECT_EQ(get(after, "/api/lenses/dgauss.50mm").status, 200);
}

TEST_F(ServerApi, RejectsABadLensWithFileAndLine) {
    auto c = client();
    const Reply bad = uploadMultipart(c, "broken.dat", "# a broken table\n50 0 1.5 20\n-50 five 1 20\n");
    ASSERT_EQ(bad.status, 400) << bad.raw;
    EXPECT_EQ(bad.body["file"], "broken.dat");
    EXPECT_EQ(bad.body["line"], 3);
    EXPECT_EQ(bad.body["error"].get<std::string>().rfind("broken.dat:3: ", 0), 0u) << bad.raw;
    EXPECT_EQ(postRaw(c, "/api/lenses", "   \n").status, 400);
    httplib::MultipartFormDataItems wrongField = {{"table", "1 2 3 4", "x.dat", "text/plain"}};
    EXPECT_EQ(c.Post("/api/lenses", wrongField)->status, 400);
}

TEST_F(ServerApi, UploadNamesNeverBecomePaths) {
    auto c = client();
    const Reply r = postRaw(c, "/api/lenses?name=../../../evil.dat", readFile(kSource + "/lenses/dgauss.dat"));
    ASSERT_EQ(r.status, 201) << r.raw;
    EXPECT_EQ(r.body["name"], "evil.dat");
    EXPECT_FALSE(std::filesystem::exists(data_.path() + "/evil.dat"));
    for (const auto& entry : std::filesystem::recursive_directory_iterator(data_.path()))
        EXPECT_EQ(entry.path().filename().string().find("evil"), std::string::npos) << entry.path();
}

// The server may answer 413 as soon as it reads the Content-Length and close while the body is
// still on its way, so the body is sent on a raw connection that tolerates the close.
TEST_F(ServerApi, RefusesOversizedBodies) {
    RawConnection connection(server_->port());
    const std::size_t size = 2 << 20;
    connection.send("POST /api/lenses HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Type: text/plain\r\nContent-Length: " +
                    std::to_string(size) + "\r\n\r\n");
    connection.send(std::string(size, '1'));
    const std::string reply = connection.readReply(10);
    EXPECT_EQ(statusOf(reply), 413) << reply.substr(0, 400);
    EXPECT_NE(reply.find("\"error\""), std::string::npos) << reply.substr(0, 400);
    auto c = client();
    EXPECT_EQ(get(c, "/api/health").status, 200);
}

TEST_F(ServerApi, RefusesPathTraversal) {
    auto c = client();
    for (const std::string path : {"/../../../../etc/passwd", "/%2e%2e/%2e%2e/etc/passwd", "/report/../../etc/passwd",
                                   "/api/lenses/..%2f..%2fetc%2fpasswd", "/api/lenses/.hidden",
                                   "/api/renders/..%2fx/image.png", "/.git/config", "/report/%2e%2e/lenslab.db"}) {
        const auto result = c.Get(path);
        ASSERT_TRUE(result) << path;
        EXPECT_GE(result->status, 400) << path;
        EXPECT_LT(result->status, 500) << path;
        EXPECT_EQ(result->body.find("root:"), std::string::npos) << path;
        EXPECT_EQ(result->body.find("SQLite"), std::string::npos) << path;
    }
    const Reply badScene = postJson(c, "/api/renders", {{"scene", "../../etc/passwd"}});
    EXPECT_EQ(badScene.status, 400);
    const Reply badLens = postJson(c, "/api/renders", {{"lens", "/etc/passwd"}});
    EXPECT_EQ(badLens.status, 400);
}

TEST_F(ServerApi, ServesThePageAndExplainsAMissingReport) {
    auto c = client();
    const auto page = c.Get("/");
    ASSERT_EQ(page->status, 200);
    EXPECT_NE(page->body.find("lenslab"), std::string::npos);
    EXPECT_EQ(c.Get("/app.js")->status, 200);
    const auto report = c.Get("/report/");
    EXPECT_EQ(report->status, 404);
    EXPECT_NE(report->body.find("lenslab report"), std::string::npos);
    std::filesystem::create_directories(data_.path() + "/data/report");
    std::ofstream(data_.path() + "/data/report/index.html") << "<html>the report</html>";
    const auto generated = c.Get("/report/");
    EXPECT_EQ(generated->status, 200);
    EXPECT_NE(generated->body.find("the report"), std::string::npos);
}

TEST_F(ServerApi, DrawsCachedDiagramsUnderConcurrentRequests) {
    // Sixteen requests of heavy work at once from one address: its share and the pool's places raised to them.
    server_.reset();
    server_ = std::make_unique<ServerProcess>(kBinary, data_.path() + "/data",
                                              std::vector<std::string>{"--work-per-client", "16", "--http-threads", "64"});
    auto c = client();
    for (const std::string mode : {"exact", "thick", "overlay"}) {
        const auto r = c.Get("/api/lenses/dgauss.50mm/diagram.png?mode=" + mode + "&fstop=2.8&focus=2000&size=600x300");
        ASSERT_EQ(r->status, 200) << mode << " " << r->body;
        EXPECT_TRUE(isPng(r->body)) << mode;
        EXPECT_EQ(r->get_header_value("Content-Type"), "image/png");
    }
    const std::string url = "/api/lenses/dgauss.50mm/diagram.png?mode=exact&fstop=4&size=400";
    const int hitsBefore = get(c, "/api/health").body["diagram_cache"]["hits"];
    std::vector<std::future<std::pair<int, std::string>>> answers;
    for (int i = 0; i < 16; ++i)
        answers.push_back(std::async(std::launch::async, [&, i] {
            httplib::Client own = server_->client();
            const std::string u = i % 2 ? url : url + "&field=" + std::to_string(5 + i);
            auto r = own.Get(u);
            return r ? std::make_pair(r->status, r->body) : std::make_pair(0, std::string());
        }));
    std::string first;
    for (auto& a : answers) {
        auto [status, body] = a.get();
        EXPECT_EQ(status, 200);
        EXPECT_TRUE(isPng(body));
    }
    const int hitsAfter = get(c, "/api/health").body["diagram_cache"]["hits"];
    EXPECT_GE(hitsAfter - hitsBefore, 7);  // 8 identical requests: one draws, the others share it

    EXPECT_EQ(c.Get("/api/lenses/dgauss.50mm/diagram.png?mode=sideways")->status, 400);
    EXPECT_EQ(c.Get("/api/lenses/dgauss.50mm/diagram.png?size=99999")->status, 400);
    EXPECT_EQ(c.Get("/api/lenses/dgauss.50mm/diagram.png?size=12xq")->status, 400);
    EXPECT_EQ(c.Get("/api/lenses/dgauss.50mm/diagram.png?fstop=0.9")->status, 422);
    EXPECT_EQ(c.Get("/api/lenses/nope/diagram.png")->status, 404);
}

TEST_F(ServerApi, ChecksEveryRenderField) {
    auto c = client();
    EXPECT_EQ(postRaw(c, "/api/renders", "{not json").status, 400);
    EXPECT_EQ(postJson(c, "/api/renders", json::array()).status, 400);
    EXPECT_EQ(postJson(c, "/api/renders", {{"spp", 100000}}).status, 400);
    EXPECT_EQ(postJson(c, "/api/renders", {{"width", 100000}}).status, 400);
    EXPECT_EQ(postJson(c, "/api/renders", {{"height", 0}}).status, 400);
    EXPECT_EQ(postJson(c, "/api/renders", {{"spp", 2.5}}).status, 400);
    EXPECT_EQ(postJson(c, "/api/renders", {{"fstop", "wide"}}).status, 400);
    EXPECT_EQ(postJson(c, "/api/renders", {{"mode", "magic"}}).status, 400);
    EXPECT_EQ(postJson(c, "/api/renders", {{"sp", 4}}).status, 400);
    const Reply unknownLens = postJson(c, "/api/renders", {{"lens", "missing"}});
    EXPECT_EQ(unknownLens.status, 400);
    EXPECT_NE(unknownLens.body["error"].get<std::string>().find("missing"), std::string::npos);
    EXPECT_EQ(get(c, "/api/renders/render-0000").status, 404);
    EXPECT_EQ(c.Post("/api/nothing", "", "text/plain")->status, 404);
}

TEST_F(ServerApi, RendersASmallSceneWithTheRayTracer) {
    auto c = client();
    const Reply scenes = get(c, "/api/scenes");
    ASSERT_EQ(scenes.status, 200);
    ASSERT_FALSE(scenes.body["scenes"].empty()) << "no scenes in " << kSource << "/scenes";
    const std::string scene = scenes.body["scenes"][0]["id"];
    const Reply submitted = postJson(c, "/api/renders",
                                     {{"scene", scene}, {"lens", "dgauss.50mm"}, {"fstop", 4}, {"focaldistance", 2000},
                                      {"mode", "exact"}, {"spp", 4}, {"width", 64}, {"height", 64}});
    ASSERT_EQ(submitted.status, 202) << submitted.raw;
    const std::string id = submitted.body["id"];
    const json done = waitForRenderState(c, id, {"done", "failed", "cancelled"}, 120);
    ASSERT_EQ(done["state"], "done") << done.dump();
    EXPECT_EQ(done["progress"]["tiles_done"], done["progress"]["tiles_total"]);
    EXPECT_GT(done["progress"]["tiles_total"].get<int>(), 0);
    const auto png = c.Get("/api/renders/" + id + "/image.png");
    ASSERT_EQ(png->status, 200);
    EXPECT_TRUE(isPng(png->body));
    const auto exr = c.Get("/api/renders/" + id + "/image.exr");
    ASSERT_EQ(exr->status, 200);
    EXPECT_TRUE(isExr(exr->body));
}

TEST_F(ServerApi, BuildsTheReportAsAJobWithProgress) {
    auto c = client();
    EXPECT_EQ(get(c, "/api/report").body["state"], "idle");
    EXPECT_EQ(remove(c, "/api/report").status, 409);  // nothing to cancel
    EXPECT_EQ(postJson(c, "/api/report", {{"spp", 0}}).status, 400);
    EXPECT_EQ(postJson(c, "/api/report", {{"lenses", {"no-such-lens"}}}).status, 404);
    EXPECT_EQ(postRaw(c, "/api/report", "{not json").status, 400);

    const Reply upload = postRaw(c, "/api/lenses?name=mine.dat", readFile(kSource + "/lenses/telephoto.dat"));
    ASSERT_EQ(upload.status, 201) << upload.raw;
    const std::string uploaded = upload.body["id"];
    const Reply started = postJson(c, "/api/report", {{"quick", true}, {"lenses", {"dgauss.50mm", uploaded}}});
    ASSERT_EQ(started.status, 202) << started.raw;
    EXPECT_EQ(started.body["state"], "running");
    const Reply second = postJson(c, "/api/report", {{"quick", true}});
    const json firstNow = get(c, "/api/report").body;
    if (firstNow["state"] == "running") {
        EXPECT_EQ(second.status, 409) << second.raw;
    }

    json status;
    for (int i = 0; i < 1500; ++i) {  // at most 300 s: a loaded machine is slow, not wrong
        status = get(c, "/api/report").body;
        if (status["state"] != "running") break;
        std::this_thread::sleep_for(std::chrono::milliseconds(200));
    }
    ASSERT_EQ(status["state"], "done") << status.dump();
    EXPECT_EQ(status["summary"]["lenses"], 2);
    EXPECT_GT(status["summary"]["renders"].get<int>(), 0);
    EXPECT_EQ(status["progress"]["done"], status["progress"]["total"]);
    const auto page = c.Get("/report/");
    ASSERT_EQ(page->status, 200);
    EXPECT_NE(page->body.find("dgauss.50mm"), std::string::npos);
    EXPECT_NE(page->body.find(uploaded), std::string::npos);
    // The upload is headed, and its command line names its file, by the name it was uploaded as.
    EXPECT_NE(page->body.find("<h3>mine.dat</h3>"), std::string::npos);
    EXPECT_NE(page->body.find("lenslab lens mine.dat"), std::string::npos);
    EXPECT_EQ(page->body.find("<h3>" + uploaded + "</h3>"), std::string::npos);
    EXPECT_EQ(page->body.find("telephoto.250mm"), std::string::npos);  // only the lenses asked for
}

// A tilt-shift render is taken; what a moved lens cannot do is refused before it is queued.
TEST_F(ServerApi, TiltAndShiftRenderAndRefuseWhatAMovedLensCannotDo) {
    auto c = client();
    const Reply tilted = postJson(c, "/api/renders", {{"scene", "depth-of-field"}, {"lens", "dgauss.50mm"}, {"tilt", 4},
                                                      {"shift", {2, 3}}, {"spp", 1}, {"width", 32}, {"height", 24}});
    EXPECT_EQ(tilted.status, 202) << tilted.raw;
    EXPECT_EQ(tilted.body["request"]["tilt"], 4) << tilted.raw;
    const Reply spectral = postJson(c, "/api/renders", {{"lens", "dgauss.50mm"}, {"tilt", 4}, {"spectral", true}});
    EXPECT_EQ(spectral.status, 422) << spectral.raw;
    EXPECT_NE(spectral.body["error"].get<std::string>().find("tilted or shifted lens renders in RGB"), std::string::npos) << spectral.raw;
    const Reply flare = postJson(c, "/api/renders", {{"lens", "dgauss.50mm"}, {"swing", 2}, {"ghosts", "all"}});
    EXPECT_EQ(flare.status, 422) << flare.raw;
    EXPECT_NE(flare.body["error"].get<std::string>().find("lens flare is not modelled"), std::string::npos) << flare.raw;
    EXPECT_EQ(postJson(c, "/api/renders", {{"lens", "dgauss.50mm"}, {"tilt", 60}}).status, 400);
}

TEST_F(ServerApi, ASensorRendersItsReadoutAndRefusesUnknownKeys) {
    auto c = client();
    const Reply noisy = postJson(c, "/api/renders", {{"scene", "depth-of-field"}, {"lens", "dgauss.50mm"},
                                                     {"sensor", {{"iso", 25600}, {"exposure", 1e-4}, {"cfa", "rggb"}}},
                                                     {"spp", 1}, {"width", 32}, {"height", 24}});
    ASSERT_EQ(noisy.status, 202) << noisy.raw;
    EXPECT_EQ(noisy.body["request"]["sensor"]["iso"], 25600) << noisy.raw;
    EXPECT_EQ(noisy.body["request"]["sensor"]["cfa"], "rggb") << noisy.raw;
    const json done = waitForRenderState(c, noisy.body["id"], {"done", "failed", "cancelled"}, 120);
    ASSERT_EQ(done["state"], "done") << done.dump();
    const auto exr = c.Get("/api/renders/" + noisy.body["id"].get<std::string>() + "/image.exr");
    ASSERT_EQ(exr->status, 200);
    EXPECT_NE(exr->body.find("ISO 25600, exposure 0.0001 s"), std::string::npos);  // the header's sensor line
    EXPECT_NE(exr->body.find("a rggb Bayer mosaic, demosaiced"), std::string::npos);
    const Reply unknown = postJson(c, "/api/renders", {{"lens", "dgauss.50mm"}, {"sensor", {{"isp", 100}}}});
    EXPECT_EQ(unknown.status, 400);
    EXPECT_NE(unknown.body["error"].get<std::string>().find("sensor: unknown key 'isp'"), std::string::npos) << unknown.raw;
    const Reply range = postJson(c, "/api/renders", {{"lens", "dgauss.50mm"}, {"sensor", {{"bits", 40}}}});
    EXPECT_EQ(range.status, 400);
    EXPECT_NE(range.body["error"].get<std::string>().find("bits must be a whole number between 1 and 24"), std::string::npos) << range.raw;
    EXPECT_EQ(postJson(c, "/api/renders", {{"lens", "dgauss.50mm"}, {"sensor", 800}}).status, 400);
    EXPECT_EQ(postJson(c, "/api/renders", {{"lens", "dgauss.50mm"}, {"sensor", {{"iso", "fast"}}}}).status, 400);
    const Reply pattern = postJson(c, "/api/renders", {{"lens", "dgauss.50mm"}, {"sensor", {{"cfa", "rgbg"}}}});
    EXPECT_EQ(pattern.status, 400);
    EXPECT_NE(pattern.body["error"].get<std::string>().find("cfa must be one of none, rggb"), std::string::npos) << pattern.raw;
}

// Lens settings are checked once, by optics, and the error names the field it came from.
TEST_F(ServerApi, RenderSettingsOutsideTheLensNameTheirField) {
    auto c = client();
    const Reply wide = postJson(c, "/api/renders", {{"lens", "dgauss.50mm"}, {"fstop", 0.7}});
    EXPECT_EQ(wide.status, 422) << wide.raw;
    EXPECT_EQ(wide.body["error"].get<std::string>().rfind("field fstop: f-number 0.7 is outside this lens's range f/2.02 to f/64", 0), 0u)
        << wide.raw;
    const Reply close = postJson(c, "/api/renders", {{"lens", "dgauss.50mm"}, {"focaldistance", 10}});
    EXPECT_EQ(close.status, 422) << close.raw;
    EXPECT_EQ(close.body["error"].get<std::string>().rfind("field focaldistance: ", 0), 0u) << close.raw;
    // The scene's own f-number (depth-of-field.pbrt: f/2.1) through a lens that cannot open so wide:
    // refused at submit, naming the scene's line and not the server's folders, not queued to fail.
    const Reply sceneWide = postJson(c, "/api/renders", {{"scene", "depth-of-field"}, {"lens", "telephoto.250mm"}});
    EXPECT_EQ(sceneWide.status, 422) << sceneWide.raw;
    EXPECT_EQ(sceneWide.body["error"].get<std::string>().rfind(
                  "depth-of-field.pbrt:7: Camera \"realistic\": fstop: f-number 2.1 is outside this lens's range f/5.6 to f/64", 0),
              0u)
        << sceneWide.raw;
    const Reply again = postJson(c, "/api/renders", {{"scene", "depth-of-field"}, {"lens", "telephoto.250mm"}});
    EXPECT_EQ(again.status, 422);  // the remembered outcome, word for word
    EXPECT_EQ(again.body, sceneWide.body);
    EXPECT_EQ(get(c, "/api/renders").body["renders"].size(), 0u);
    EXPECT_EQ(postJson(c, "/api/renders", {{"scene", "depth-of-field"}, {"lens", "telephoto.250mm"}, {"fstop", 8},
                                           {"spp", 1}, {"width", 16}, {"height", 16}})
                  .status,
              202);
    // The lens's own f-number range, as the API reports it, ends at the documented f/64.
    EXPECT_EQ(get(c, "/api/lenses/dgauss.50mm").body["fstop_max"], 64);
}

// A gap-after table whose last gap is not 0 needs ?layout=gap-after to be read; the render must use
// that layout too (it used to re-detect and fail).
TEST_F(ServerApi, UploadedLensRendersWithTheLayoutItWasCheckedWith) {
    auto c = client();
    std::string table = readFile(kSource + "/lenses/dgauss.50mm.dat");
    const std::string lastRow = "-39.73 0 1 20";
    ASSERT_NE(table.find(lastRow), std::string::npos);
    table.replace(table.find(lastRow), lastRow.size(), "-39.73 5 1 20");
    EXPECT_EQ(postRaw(c, "/api/lenses?name=gap-after.dat", table).status, 400);  // cannot tell the layout
    const Reply uploaded = postRaw(c, "/api/lenses?name=gap-after.dat&layout=gap-after", table);
    ASSERT_EQ(uploaded.status, 201) << uploaded.raw;
    const Reply scenes = get(c, "/api/scenes");
    const Reply submitted = postJson(c, "/api/renders", {{"scene", scenes.body["scenes"][0]["id"]}, {"lens", uploaded.body["id"]},
                                                         {"fstop", 4}, {"spp", 1}, {"width", 32}, {"height", 32}});
    ASSERT_EQ(submitted.status, 202) << submitted.raw;
    const json done = waitForRenderState(c, submitted.body["id"], {"done", "failed", "cancelled"}, 120);
    EXPECT_EQ(done["state"], "done") << done.dump();
}

// A lens that blocks most camera rays says so in its render's record (issue 38), kept across a
// restart: a stop, a singlet (EFL 80.4 mm) and 60 mm behind it a 4 mm baffle, an image circle
// 7.48 mm across on a 35 mm film (tests/renderer/test_render_warnings.cpp): 7.5% of it lit.
TEST_F(ServerApi, ARenderSaysWhatItsLensLeavesBlack) {
    auto c = client();
    const Reply uploaded = postRaw(c, "/api/lenses?name=baffled.dat", "0 0 0 6\n50 2 1.5 20\n-200 4 0 20\n0 60 1 4\n");
    ASSERT_EQ(uploaded.status, 201) << uploaded.raw;
    const Reply submitted = postJson(c, "/api/renders", {{"scene", "shared-dgauss"}, {"lens", uploaded.body["id"]}, {"fstop", 16},
                                                         {"focaldistance", 1000}, {"filmdiagonal", 35}, {"spp", 1},
                                                         {"width", 32}, {"height", 24}});
    ASSERT_EQ(submitted.status, 202) << submitted.raw;
    const std::string id = submitted.body["id"];
    const json done = waitForRenderState(c, id, {"done", "failed", "cancelled"}, 60);
    ASSERT_EQ(done["state"], "done") << done.dump();
    const json expected = {"the lens blocks 92.4% of the camera rays: most of the frame is dark",
                           "the lens's image circle (7.48 mm across on the film) is smaller than the film (35.00 mm diagonal): "
                           "beyond it the frame is black"};
    EXPECT_EQ(done["warnings"], expected);
    restart();
    auto after = client();
    EXPECT_EQ(get(after, "/api/renders/" + id).body["warnings"], expected);
    EXPECT_EQ(get(after, "/api/renders").body["renders"][0]["warnings"], expected);
}

// SIGTERM after serving stops the server cleanly: exit status 0, no abort on the way out (the
// worker pool was once shut down twice, which threw from its join).
TEST_F(ServerApi, StopsCleanlyOnSigterm) {
    auto c = client();
    EXPECT_EQ(get(c, "/api/health").status, 200);
    const int status = server_->stop();
    EXPECT_TRUE(WIFEXITED(status)) << "killed by signal " << (WIFSIGNALED(status) ? WTERMSIG(status) : 0) << "\n"
                                   << server_->output();
    EXPECT_EQ(WEXITSTATUS(status), 0) << server_->output();
}

// Issue 40, finding 3: the flare of an 80-surface lens (3,160 ghost paths, minutes of setup) is
// cancelled within a couple of seconds of the DELETE, and SIGTERM in the same setup stops the
// server within 5 s: the flare's setup checks the cancel flag per ghost.
TEST_F(ServerApi, ALongFlareSetupHonoursCancelAndSigterm) {
    using Clock = std::chrono::steady_clock;
    std::string table;
    for (int element = 0; element < 40; ++element) {
        table += "2000 2 1.5 20\n-2000 " + std::string(element == 39 ? "0" : "1") + " 1 20\n";
        if (element == 19) table += "0 1 0 16\n";
    }
    auto c = client();
    const Reply uploaded = postRaw(c, "/api/lenses?name=eighty.dat", table);
    ASSERT_EQ(uploaded.status, 201) << uploaded.raw;
    const json flare = {{"scene", "sun-flare"}, {"lens", uploaded.body["id"]}, {"ghosts", "all"},
                        {"spp", 1}, {"width", 32}, {"height", 24}};
    const Reply first = postJson(c, "/api/renders", flare);
    ASSERT_EQ(first.status, 202) << first.raw;
    ASSERT_EQ(waitForRenderState(c, first.body["id"], {"running"}, 10)["state"], "running");
    std::this_thread::sleep_for(std::chrono::milliseconds(1500));  // past the camera's setup, into the flare's
    const auto cancelledAt = Clock::now();
    EXPECT_EQ(remove(c, "/api/renders/" + first.body["id"].get<std::string>()).status, 202);
    EXPECT_EQ(waitForRenderState(c, first.body["id"], {"cancelled"}, 2)["state"], "cancelled");
    EXPECT_LT(std::chrono::duration<double>(Clock::now() - cancelledAt).count(), 2.0);

    const Reply second = postJson(c, "/api/renders", flare);
    ASSERT_EQ(waitForRenderState(c, second.body["id"], {"running"}, 10)["state"], "running");
    std::this_thread::sleep_for(std::chrono::milliseconds(1500));
    const auto stoppedAt = Clock::now();
    const int status = server_->stop();
    EXPECT_LT(std::chrono::duration<double>(Clock::now() - stoppedAt).count(), 5.0);
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << server_->output();
}
