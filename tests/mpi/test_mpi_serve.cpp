// `lenslab serve --mpi-hostfile H --mpi-np 3`: a render job runs through mpirun and reports its
// tiles and statistics like a local job.
#include <gtest/gtest.h>

#include <fstream>

#include "ServerProcess.h"

namespace lenslab {
namespace {

std::string writeHostfile(const test::TempDir& dir) {
    const std::string path = dir.path() + "/hosts";
    std::ofstream(path) << "localhost slots=3\n";
    return path;
}

// A service whose renders run through mpirun with three processes on this host (members are
// initialised in order: the hostfile exists before the server starts).
class MpiServe : public ::testing::Test {
protected:
    test::TempDir dir;
    const std::string hostfile = writeHostfile(dir);
    test::ServerProcess server{LENSLAB_BINARY, dir.path() + "/data", {"--mpi-hostfile", hostfile, "--mpi-np", "3"}};
    httplib::Client client = server.client();
};

TEST_F(MpiServe, RenderJobRunsThroughMpirun) {
    const test::Reply created = test::postJson(
        client, "/api/renders", {{"scene", "shared-dgauss"}, {"spp", 2}, {"width", 64}, {"height", 48}});
    ASSERT_EQ(created.status, 202) << created.raw;
    const std::string id = created.body["id"];
    const nlohmann::json job = test::waitForRenderState(client, id, {"done", "failed", "cancelled"}, 60);
    ASSERT_EQ(job["state"], "done") << job.dump() << "\n" << server.output();
    EXPECT_EQ(job["stats"]["mpi_processes"], 3);
    EXPECT_EQ(job["stats"]["camera_rays"], 64 * 48 * 2);
    EXPECT_EQ(job["progress"]["tiles_done"], job["progress"]["tiles_total"]);
    EXPECT_TRUE(test::isPng(test::get(client, "/api/renders/" + id + "/image.png").raw));
    EXPECT_TRUE(test::isExr(test::get(client, "/api/renders/" + id + "/image.exr").raw));
}

TEST_F(MpiServe, CancelStopsTheMpirunJob) {
    const test::Reply created = test::postJson(
        client, "/api/renders", {{"scene", "shared-dgauss"}, {"spp", 1024}, {"width", 320}, {"height", 240}});
    ASSERT_EQ(created.status, 202) << created.raw;
    const std::string id = created.body["id"];
    ASSERT_EQ(test::waitForRenderState(client, id, {"running"}, 30)["state"], "running");
    EXPECT_EQ(test::remove(client, "/api/renders/" + id).status, 202);
    const nlohmann::json job = test::waitForRenderState(client, id, {"done", "failed", "cancelled"}, 30);
    EXPECT_EQ(job["state"], "cancelled") << job.dump() << "\n" << server.output();
}

}  // namespace
}  // namespace lenslab
