// `lenslab serve --mpi-hostfile H --mpi-np 3`: a render job runs through mpirun and reports its
// tiles and statistics like a local job.
#include <gtest/gtest.h>

#include <fstream>

#include "ServerProcess.h"

namespace lenslab {
namespace {

TEST(MpiServe, RenderJobRunsThroughMpirun) {
    test::TempDir dir;
    const std::string hostfile = dir.path() + "/hosts";
    std::ofstream(hostfile) << "localhost slots=3\n";
    test::ServerProcess server(LENSLAB_BINARY, dir.path() + "/data", {"--mpi-hostfile", hostfile, "--mpi-np", "3"});
    httplib::Client client = server.client();
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

TEST(MpiServe, CancelStopsTheMpirunJob) {
    test::TempDir dir;
    const std::string hostfile = dir.path() + "/hosts";
    std::ofstream(hostfile) << "localhost slots=3\n";
    test::ServerProcess server(LENSLAB_BINARY, dir.path() + "/data", {"--mpi-hostfile", hostfile, "--mpi-np", "3"});
    httplib::Client client = server.client();
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
