// Optimisation and tolerancing as jobs of the service (docs/api.md, "Optimising and tolerancing"):
// the Cooke triplet of docs/design.md uploaded with its curvatures 5% off, optimised over HTTP to a
// lens whose returned .zmx reads back at the job's end merit; a seeded Monte Carlo whose histograms
// hold every valid trial; bad inputs 400 naming the field; a DELETE honoured within a second; the
// per-client share and the token held as on the other heavy routes.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <fstream>
#include <regex>
#include <sstream>
#include <thread>

#include "FileText.h"
#include "DesignJson.h"
#include "ServerProcess.h"
#include "design/MeritFunction.h"
#include "prescription/ZemaxFile.h"

using namespace lenslab;
using namespace lenslab::test;
using nlohmann::json;
using Clock = std::chrono::steady_clock;

namespace {

const std::string kSource = LENSLAB_SOURCE_DIR;

// docs/design.md's starting point: each of the six curvatures 5% off, alternately + and -.
std::string perturbedCooke() {
    const std::string zmx = readFile(kSource + "/lenses/design/cooke-triplet-50mm.zmx");
    const std::regex curvature(R"(CURV (-?[0-9.]+e[-+][0-9]+))");
    std::string out;
    auto at = zmx.cbegin();
    int k = 0;
    for (std::sregex_iterator m(zmx.begin(), zmx.end(), curvature), end; m != end; ++m) {
        out.append(at, (*m)[0].first);
        std::ostringstream s;
        s.precision(17);
        s << "CURV " << std::stod((*m)[1]) * (k++ % 2 ? 0.95 : 1.05);
        out += s.str();
        at = (*m)[0].second;
    }
    out.append(at, zmx.cend());
    return out;
}

const json kCookeMerit = json::parse(readFile(kSource + "/bench/design/cooke-merit.json"));

class ServerDesign : public ::testing::Test {
protected:
    void SetUp() override {
        server_ = std::make_unique<ServerProcess>(binaryUnderTest(), data_.path() + "/data");
        auto c = server_->client();
        const Reply upload = postRaw(c, "/api/lenses?name=cooke-perturbed.zmx", perturbedCooke());
        ASSERT_EQ(upload.status, 201) << upload.raw;
        lens_ = upload.body["id"];
    }

    Reply submit(const std::string& kind, const json& body) {
        auto c = server_->client();
        return postJson(c, "/api/lenses/" + lens_ + "/" + kind, body);
    }

    // Polls the job until it is over; its last status.
    json waitUntilOver(const std::string& id, double seconds = 60) {
        auto c = server_->client();
        const auto deadline = Clock::now() + std::chrono::duration<double>(seconds);
        for (;;) {
            const Reply r = get(c, "/api/design-jobs/" + id);
            EXPECT_EQ(r.status, 200) << r.raw;
            const std::string state = r.body.value("state", "");
            if (state == "done" || state == "failed" || state == "cancelled" || Clock::now() > deadline) return r.body;
            std::this_thread::sleep_for(std::chrono::milliseconds(50));
        }
    }

    TempDir data_;
    std::unique_ptr<ServerProcess> server_;
    std::string lens_;
};

// Every `data:` line of the job's event stream, read to its end.
std::vector<json> eventsOf(httplib::Client& c, const std::string& id) {
    std::string text;
    c.set_read_timeout(30, 0);
    c.Get(("/api/design-jobs/" + id + "/events").c_str(), [&](const char* data, std::size_t n) {
        text.append(data, n);
        return true;
    });
    std::vector<json> events;
    std::istringstream lines(text);
    for (std::string line; std::getline(lines, line);)
        if (line.rfind("data: ", 0) == 0) events.push_back(json::parse(line.substr(6)));
    return events;
}

}  // namespace

TEST_F(ServerDesign, OptimiseReturnsTheOptimisedLensAtItsEndMerit) {
    const Reply submitted = submit("optimise", {{"merit", kCookeMerit}, {"variables", "curvature:1-6"}});
    ASSERT_EQ(submitted.status, 202) << submitted.raw;
    EXPECT_EQ(submitted.header("Location"), "/api/design-jobs/" + submitted.body["id"].get<std::string>());
    auto c = server_->client();
    const std::vector<json> events = eventsOf(c, submitted.body["id"]);
    ASSERT_FALSE(events.empty());
    EXPECT_EQ(events.back()["state"], "done") << events.back().dump();
    const json job = waitUntilOver(submitted.body["id"]);
    ASSERT_EQ(job["state"], "done") << job.dump();
    EXPECT_EQ(job, events.back());  // the stream's last event is the finished job, result included

    const json& optimiser = job["result"]["optimiser"];
    const double start = optimiser["start"]["merit"], end = optimiser["end"]["merit"];
    EXPECT_LT(end, 0.2 * start);  // 5% curvature errors are mostly undone (docs/design.md: 0.0243 -> 0.00043)
    const std::vector<double> history = job["progress"]["history"];
    ASSERT_FALSE(history.empty());
    for (std::size_t i = 1; i < history.size(); ++i) EXPECT_LE(history[i], history[i - 1]);
    EXPECT_DOUBLE_EQ(history.back(), end);

    // The uploaded lens is the start; the returned .zmx, read back, is the end.
    const LensTable before = parseZemax(perturbedCooke(), "before.zmx");
    const LensTable after = parseZemax(job["result"]["zmx"].get<std::string>(), "after.zmx");
    const MeritFunction merit = meritFromJson(kCookeMerit, before);
    EXPECT_NEAR(evaluateMerit(before, merit).merit, start, 1e-12 * start);
    const MeritEvaluation readBack = evaluateMerit(after, merit);
    ASSERT_TRUE(readBack.valid) << readBack.problem;
    EXPECT_NEAR(readBack.merit, end, 1e-9 * end);
    // The editor's rows: the same surfaces, their radii the optimised curvatures.
    const json& rows = job["result"]["prescription"]["rows"];
    ASSERT_EQ(rows.size(), after.rows.size());
    for (std::size_t i = 0; i < rows.size(); ++i) EXPECT_NEAR(rows[i]["radius"].get<double>(), after.rows[i].radius, 1e-9 * std::fabs(after.rows[i].radius));
    EXPECT_EQ(optimiser["variables"].size(), 6u);
}

TEST_F(ServerDesign, ToleranceCountsEveryTrialInItsHistograms) {
    const json tolerances = json::parse(readFile(kSource + "/bench/design/cooke-tolerances.json"));
    const json body = {{"merit", kCookeMerit}, {"tolerances", tolerances}, {"trials", 40}, {"seed", 7}};
    const Reply submitted = submit("tolerance", body);
    ASSERT_EQ(submitted.status, 202) << submitted.raw;
    const json job = waitUntilOver(submitted.body["id"]);
    ASSERT_EQ(job["state"], "done") << job.dump();
    const json& mc = job["result"]["monte_carlo"];
    EXPECT_EQ(mc["trials"], 40);
    EXPECT_EQ(job["progress"]["trials_done"], 40);
    const int valid = 40 - mc["invalid"].get<int>();
    EXPECT_GT(valid, 30);
    const auto checkDistribution = [&](const json& d) {
        int sum = 0;
        for (const json& bin : d["histogram"]) sum += bin.get<int>();
        EXPECT_EQ(d["count"], valid);
        EXPECT_EQ(sum, valid);
        EXPECT_LE(d["min"].get<double>(), d["p50"].get<double>());
        EXPECT_LE(d["p50"].get<double>(), d["p90"].get<double>());
        EXPECT_LE(d["p90"].get<double>(), d["p98"].get<double>());
        EXPECT_LE(d["p98"].get<double>(), d["max"].get<double>());
    };
    checkDistribution(mc["merit"]);
    ASSERT_EQ(mc["operands"].size(), kCookeMerit["operands"].size());
    for (const json& op : mc["operands"]) checkDistribution(op["distribution"]);
    EXPECT_FALSE(job["result"]["sensitivity"].empty());
    EXPECT_EQ(job["result"]["seed"], 7);

    // Seeded: the same request gives the same trials.
    const Reply again = submit("tolerance", body);
    ASSERT_EQ(again.status, 202);
    EXPECT_EQ(waitUntilOver(again.body["id"])["result"]["monte_carlo"], mc);
}

TEST_F(ServerDesign, BadInputsAreRefusedNamingTheField) {
    const auto refused = [&](const std::string& kind, const json& body, const std::string& field, const std::string& words) {
        const Reply r = submit(kind, body);
        EXPECT_EQ(r.status, 400) << body.dump() << " " << r.raw;
        EXPECT_EQ(r.body.value("field", ""), field) << r.raw;
        EXPECT_NE(r.body.value("error", "").find(words), std::string::npos) << r.raw;
    };
    refused("optimise", {{"merit", {{"operands", {{{"type", "sharpness"}}}}}}}, "merit", "unknown operand type 'sharpness'");
    refused("optimise", {{"merit", {{"operands", json::array()}}}}, "merit", "no operands");
    refused("optimise", {{"variables", "curvature:9"}}, "variables", "surfaces run from 1 to 6");
    refused("optimise", {{"variables", "bending:2"}}, "variables", "unknown kind 'bending'");
    refused("optimise", {{"variables", "curvature:2,curvature:2"}}, "variables", "given twice");
    refused("optimise", {{"max_iterations", 0}}, "max_iterations", "from 1 to 200");
    refused("optimise", {{"merrit", json::object()}}, "merrit", "unknown field");
    refused("tolerance", {{"trials", 2001}}, "trials", "from 0 to 2000");
    refused("tolerance", {{"tolerances", {{"radios", 0.001}}}}, "tolerances", "unknown key 'radios'");
    refused("tolerance", {{"merit", {{"operands", {{{"type", "efl"}, {"weight", -1}}}}}}}, "merit", "weight");
    auto c = server_->client();
    EXPECT_EQ(postJson(c, "/api/lenses/no-such-lens/optimise", json::object()).status, 404);
    EXPECT_EQ(get(c, "/api/design-jobs/design-0000000000000000").status, 404);
    EXPECT_EQ(get(c, "/api/design-jobs/-x").status, 400);
    EXPECT_EQ(postRaw(c, "/api/lenses/" + lens_ + "/optimise", std::string(70 * 1024, ' ')).status, 413);
    // A starting lens the merit cannot trace fails the job with the reason (as lenslab optimise says
    // it): no ray of an 80 degree field reaches dgauss.50mm's image.
    const json beyondTheField = {{"merit", {{"operands", {{{"type", "rms_spot"}, {"field", 80}}}}}}};
    const Reply dgauss = postJson(c, "/api/lenses/dgauss.50mm/optimise", beyondTheField);
    ASSERT_EQ(dgauss.status, 202) << dgauss.raw;
    const json failed = waitUntilOver(dgauss.body["id"]);
    EXPECT_EQ(failed["state"], "failed");
    EXPECT_NE(failed.value("error", "").find("not valid"), std::string::npos) << failed.dump();
    EXPECT_NE(failed.value("error", "").find("80 deg field"), std::string::npos) << failed.dump();
}

TEST_F(ServerDesign, CancellationIsHonouredWithinASecond) {
    const Reply submitted = submit("tolerance", {{"trials", 2000}});
    ASSERT_EQ(submitted.status, 202) << submitted.raw;
    const std::string id = submitted.body["id"];
    auto c = server_->client();
    const auto deadline = Clock::now() + std::chrono::seconds(30);
    json status;
    // Well into the Monte Carlo trials; a job still queued (a loaded machine) has no progress yet.
    const auto trialsDone = [](const json& s) {
        return s.contains("progress") && s["progress"].is_object() ? s["progress"].value("trials_done", 0) : 0;
    };
    do {
        status = get(c, "/api/design-jobs/" + id).body;
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    } while (trialsDone(status) < 20 && Clock::now() < deadline);
    ASSERT_EQ(status["state"], "running") << status.dump();

    const auto asked = Clock::now();
    const Reply cancel = remove(c, "/api/design-jobs/" + id);
    EXPECT_EQ(cancel.status, 202) << cancel.raw;
    const json over = waitUntilOver(id, 5);
    const double seconds = std::chrono::duration<double>(Clock::now() - asked).count();
    EXPECT_EQ(over["state"], "cancelled") << over.dump();
    EXPECT_LT(seconds, 1.0);
    EXPECT_LT(over["progress"]["trials_done"].get<int>(), 2000);
    EXPECT_FALSE(over.contains("result"));

    // A finished job is forgotten by a second DELETE.
    EXPECT_EQ(remove(c, "/api/design-jobs/" + id).status, 200);
    EXPECT_EQ(get(c, "/api/design-jobs/" + id).status, 404);
}

TEST_F(ServerDesign, JobsHoldTheClientsShareOfTheHeavyWorkPool) {
    // --work-per-client 4 (the default): a fifth job of one client waits for one of its four to end.
    std::vector<std::string> ids;
    for (int i = 0; i < 4; ++i) {
        const Reply r = submit("tolerance", {{"trials", 2000}});
        ASSERT_EQ(r.status, 202) << r.raw;
        ids.push_back(r.body["id"]);
    }
    const Reply fifth = submit("optimise", json::object());
    EXPECT_EQ(fifth.status, 429) << fifth.raw;
    EXPECT_FALSE(fifth.header("Retry-After").empty());
    auto c = server_->client();
    for (const std::string& id : ids) {
        const int status = remove(c, "/api/design-jobs/" + id).status;
        EXPECT_TRUE(status == 200 || status == 202) << status;  // queued: cancelled at once; running: at its next poll
    }
    for (const std::string& id : ids) EXPECT_EQ(waitUntilOver(id, 5)["state"], "cancelled");
    EXPECT_EQ(submit("optimise", json::object()).status, 202);
}

TEST(ServerDesignAccess, SubmittingNeedsTheTokenReadingDoesNot) {
    TempDir data;
    ServerProcess server(binaryUnderTest(), data.path() + "/data", {"--token-file", data.path() + "/token"});
    auto c = server.client();
    const Reply refused = postJson(c, "/api/lenses/dgauss.50mm/optimise", json::object());
    EXPECT_EQ(refused.status, 401) << refused.raw;
    c.set_bearer_token_auth(readFile(data.path() + "/token").substr(0, 48));
    const Reply accepted = postJson(c, "/api/lenses/dgauss.50mm/tolerance", {{"trials", 0}});
    ASSERT_EQ(accepted.status, 202) << accepted.raw;
    httplib::Client anonymous = server.client();
    EXPECT_EQ(get(anonymous, "/api/design-jobs/" + accepted.body["id"].get<std::string>()).status, 200);
}
