#pragma once
// Test helpers: a service process started on a free loopback port
// (`serve --port 0`), stopped with SIGTERM or killed with SIGKILL.
#include <httplib.h>
#include <nlohmann/json.hpp>
#include <sys/types.h>

#include <memory>
#include <set>
#include <string>
#include <vector>

#include "TempDir.h"

namespace lenslab::test {

class ServerProcess {
public:
    // Starts `binary serve --port 0 --data dataDir extraArgs...` and waits until it listens.
    ServerProcess(const std::string& binary, const std::string& dataDir, const std::vector<std::string>& extraArgs = {});
    ~ServerProcess();  // stop()
    ServerProcess(const ServerProcess&) = delete;
    ServerProcess& operator=(const ServerProcess&) = delete;

    int port() const { return port_; }
    pid_t pid() const { return pid_; }
    httplib::Client client() const;
    // SIGTERM, then waits (SIGKILL after 20 s); the exit status as waitpid gives it (-1: not running).
    int stop();
    void kill9();  // SIGKILL, then waits
    std::string output() const;  // everything it printed

private:
    int wait();
    pid_t pid_ = -1;
    int port_ = 0;
    std::string logPath_;
};

// A server whose files may grow to `fileSizeLimit` bytes at most (RLIMIT_FSIZE, inherited across
// fork and exec): writing past it fails with EFBIG, as on a full disk.
std::unique_ptr<ServerProcess> startWithFileSizeLimit(const std::string& binary, const std::string& dataDir,
                                                      const std::vector<std::string>& extraArgs, std::size_t fileSizeLimit);

// GET/POST/DELETE helpers returning status and the parsed JSON body (null when not JSON).
struct Reply {
    int status = 0;
    nlohmann::json body;
    std::string raw;
    std::string header(const std::string& name) const;
    httplib::Headers headers;
};
Reply get(httplib::Client& client, const std::string& path);
Reply postJson(httplib::Client& client, const std::string& path, const nlohmann::json& body);
Reply postRaw(httplib::Client& client, const std::string& path, const std::string& body);
Reply remove(httplib::Client& client, const std::string& path);

// `readers` GETs of `path` sent together, each on a connection of its own: the distinct bodies of
// the 200 answers, how many there were, and how many answers were neither 200 nor 429 (the
// heavy-work pool's refusal of a reader past its share).
struct ConcurrentReads {
    std::set<std::string> bodies;
    int answered = 0, unexpected = 0;
};
ConcurrentReads readAtOnce(const ServerProcess& server, const std::string& path, int readers);

bool isPng(const std::string& bytes);
bool isExr(const std::string& bytes);

// Polls GET /api/renders/{id} until its state is one of `states` (or the timeout passes);
// returns the last status.
nlohmann::json waitForRenderState(httplib::Client& client, const std::string& id,
                                  const std::vector<std::string>& states, double timeoutSeconds);

// The lenslab binary the tests start: LENSLAB_SERVER_BINARY when set (to try the tests on another
// build, e.g. an older one), else this build's.
std::string binaryUnderTest();
// The fake-render server likewise: LENSLAB_FAKE_SERVER_BINARY when set, else this build's.
std::string fakeServerUnderTest();

// Writes folder/any.pbrt: a scene the fake renderer never draws, but valid as far as the service's
// submit checks read it (a realistic camera for the request's lens, a world).
void writeFakeRendererScene(const std::string& folder);

// The fake-render server over a fresh data folder, its scenes folder holding any.pbrt.
struct FakeRenderService {
    TempDir data, scenes;
    ServerProcess server;
    explicit FakeRenderService(const std::vector<std::string>& extraArgs = {});
};

// A small valid lens table (a singlet and a stop).
inline const std::string kSmallLensTable = "50.0 5.0 1.5 20.0\n-50.0 45.0 1.0 20.0\n0.0 0.0 0.0 15.0\n";

}  // namespace lenslab::test
