// Input checks from issue 23 (findings 9, 10 and 14): every documented diagram size draws and
// every other is 400, report requests are bounded, errors quote input briefly, descriptions keep
// no control characters, numbers are plain decimals within range, and a running render's preview
// is not re-encoded for every reader.
#include <gtest/gtest.h>

#include <fstream>
#include <thread>

#include "ServerProcess.h"

using namespace lenslab::test;
using nlohmann::json;

namespace {

class ServerValidation : public ::testing::Test {
protected:
    void SetUp() override {
        writeFakeRendererScene(scenes_.path());
        server_ = std::make_unique<ServerProcess>(fakeServerUnderTest(), data(), std::vector<std::string>{"--scenes", scenes_.path()});
    }
    std::string data() const { return data_.path() + "/data"; }
    static bool isJsonError(const Reply& r) { return r.body.is_object() && r.body.contains("error"); }

    TempDir data_, scenes_;
    std::unique_ptr<ServerProcess> server_;
};

}  // namespace

// Finding 9.
TEST_F(ServerValidation, EveryDocumentedDiagramSizeDrawsAndOthersAre400) {
    auto c = server_->client();
    const std::string diagram = "/api/lenses/dgauss.50mm/diagram.png?size=";
    for (const char* size : {"320x200", "2400x1600", "320x1600", "2400x200", "800"}) {
        const Reply r = get(c, diagram + size);
        EXPECT_EQ(r.status, 200) << size << " " << r.raw.substr(0, 200);
        EXPECT_TRUE(isPng(r.raw)) << size;
    }
    for (const char* size : {"200x100", "319x200", "1000x150", "2400x100", "4294967496x500", "800x4294967496", "0x10",
                             "-800x400", "800x400x", "x400", "300"}) {
        const Reply r = get(c, diagram + size);
        EXPECT_EQ(r.status, 400) << size;
        EXPECT_TRUE(isJsonError(r)) << size << " " << r.raw.substr(0, 200);
    }
}

// Finding 10.
TEST_F(ServerValidation, ReportRequestsAreBoundedAndUnknownFieldsRefused) {
    auto c = server_->client();
    const Reply bogus = postJson(c, "/api/report", {{"bogus", 1}});
    EXPECT_EQ(bogus.status, 400) << bogus.raw;
    EXPECT_TRUE(isJsonError(bogus));
    const Reply many = postJson(c, "/api/report", {{"quick", true}, {"lenses", std::vector<std::string>(20000, "dgauss.50mm")}});
    EXPECT_EQ(many.status, 400) << many.raw.substr(0, 200);
    const Reply twice = postJson(c, "/api/report", {{"quick", true}, {"lenses", {"dgauss.50mm", "dgauss.50mm"}}});
    EXPECT_EQ(twice.status, 202) << twice.raw;
    remove(c, "/api/report");
    for (int i = 0; i < 100 && get(c, "/api/report").body.value("state", "") == "running"; ++i)
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
}

// Finding 14: descriptions without control characters or bidirectional overrides.
TEST_F(ServerValidation, DescriptionsKeepNoControlCharacters) {
    auto c = server_->client();
    const Reply r = postRaw(c, "/api/lenses?name=d.dat", "# Evil\xe2\x80\xaegnp.exe\x01\x1b[31m red\n" + kSmallLensTable);
    ASSERT_EQ(r.status, 201) << r.raw;
    const std::string description = get(c, "/api/lenses/" + r.body["id"].get<std::string>()).body.value("description", "");
    EXPECT_EQ(description.find("\xe2\x80\xae"), std::string::npos) << description;
    EXPECT_EQ(description.find('\x01'), std::string::npos) << description;
    EXPECT_EQ(description.find('\x1b'), std::string::npos) << description;
    EXPECT_NE(description.find("Evil"), std::string::npos) << description;
}

// Finding 14: numbers are plain decimals in their documented range, and bad input is quoted briefly.
TEST_F(ServerValidation, NumbersArePlainDecimalsInRange) {
    auto c = server_->client();
    for (const char* fstop : {"4%00", "0x10", "4%20", "inf"}) {
        const Reply r = get(c, std::string("/api/lenses/dgauss.50mm?fstop=") + fstop);
        EXPECT_EQ(r.status, 400) << fstop << " " << r.raw;
    }
    EXPECT_EQ(get(c, "/api/lenses/dgauss.50mm?fstop=4").status, 200);
    const Reply far = postJson(c, "/api/renders", {{"scene", "any"}, {"focaldistance", 1e8}});
    EXPECT_EQ(far.status, 400) << far.raw;
    const Reply huge = postRaw(c, "/api/lenses?name=n.dat", "50 " + std::string(500000, '9') + "x 1.5 20\n" + kSmallLensTable);
    EXPECT_EQ(huge.status, 400);
    EXPECT_LT(huge.raw.size(), 2000u);
}

// Finding 14: readers of a running render's preview share one encoding a second.
TEST_F(ServerValidation, APreviewIsEncodedAtMostOnceASecond) {
    auto c = server_->client();
    const Reply job = postJson(c, "/api/renders", {{"scene", "any"}, {"spp", 20}, {"width", 320}, {"height", 240}});
    ASSERT_EQ(job.status, 202) << job.raw;
    const std::string id = job.body["id"];
    waitForRenderState(c, id, {"running"}, 10);
    std::string first;
    for (int i = 0; i < 50 && first.empty(); ++i) {
        const Reply r = get(c, "/api/renders/" + id + "/preview.png");
        if (r.status == 200) first = r.raw;
        else std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    ASSERT_FALSE(first.empty());
    std::this_thread::sleep_for(std::chrono::milliseconds(300));  // 15 more tiles meanwhile
    EXPECT_EQ(get(c, "/api/renders/" + id + "/preview.png").raw, first);
    remove(c, "/api/renders/" + id);
}
