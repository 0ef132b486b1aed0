#include "ServerProcess.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <thread>

namespace lenslab::test {

namespace fs = std::filesystem;

ServerProcess::ServerProcess(const std::string& binary, const std::string& dataDir,
                             const std::vector<std::string>& extraArgs) {
    // A server that answers 413 and closes while a test's client still sends the body (as it may,
    // before 100 Continue) makes the client's write fail: an error to check, not a SIGPIPE that
    // ends the test process.
    ::signal(SIGPIPE, SIG_IGN);
    static int started = 0;
    logPath_ = dataDir + "-server-" + std::to_string(::getpid()) + "-" + std::to_string(started++) + ".log";
    std::vector<std::string> args = {binary};
    if (fs::path(binary).filename() == "lenslab") args.push_back("serve");
    for (const std::string& a : {std::string("--port"), std::string("0"), std::string("--data"), dataDir}) args.push_back(a);
    args.insert(args.end(), extraArgs.begin(), extraArgs.end());
    pid_ = ::fork();
    if (pid_ < 0) throw std::runtime_error("fork failed");
    if (pid_ == 0) {
        const int fd = ::open(logPath_.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        ::dup2(fd, 1);
        ::dup2(fd, 2);
        std::vector<char*> argv;
        for (std::string& a : args) argv.push_back(a.data());
        argv.push_back(nullptr);
        ::execv(binary.c_str(), argv.data());
        ::_exit(127);
    }
    const std::regex listening(R"(listening on http://[^:]+:(\d+)/)");
    for (int attempt = 0; attempt < 600; ++attempt) {
        std::smatch m;
        const std::string text = output();
        if (std::regex_search(text, m, listening)) {
            port_ = std::stoi(m[1]);
            return;
        }
        int status = 0;
        if (::waitpid(pid_, &status, WNOHANG) == pid_) {
            pid_ = -1;
            throw std::runtime_error("the server exited at start:\n" + text);
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    kill9();
    throw std::runtime_error("the server did not start listening within 30 s:\n" + output());
}

ServerProcess::~ServerProcess() {
    stop();
    std::error_code ec;
    fs::remove(logPath_, ec);
}

httplib::Client ServerProcess::client() const {
    httplib::Client c("127.0.0.1", port_);
    c.set_connection_timeout(5);
    c.set_read_timeout(30);
    return c;
}

int ServerProcess::stop() {
    if (pid_ <= 0) return -1;
    ::kill(pid_, SIGTERM);
    for (int i = 0; i < 400; ++i) {
        int status = 0;
        if (::waitpid(pid_, &status, WNOHANG) == pid_) {
            pid_ = -1;
            return status;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    ::kill(pid_, SIGKILL);
    return wait();
}

void ServerProcess::kill9() {
    if (pid_ <= 0) return;
    ::kill(pid_, SIGKILL);
    wait();
}

int ServerProcess::wait() {
    int status = 0;
    ::waitpid(pid_, &status, 0);
    pid_ = -1;
    return status;
}

std::string ServerProcess::output() const {
    std::ifstream in(logPath_);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

std::unique_ptr<ServerProcess> startWithFileSizeLimit(const std::string& binary, const std::string& dataDir,
                                                      const std::vector<std::string>& extraArgs, std::size_t fileSizeLimit) {
    rlimit saved{};
    ::getrlimit(RLIMIT_FSIZE, &saved);
    rlimit limited = saved;
    limited.rlim_cur = fileSizeLimit;
    const auto previous = ::signal(SIGXFSZ, SIG_IGN);  // a write past the limit fails with EFBIG instead
    ::setrlimit(RLIMIT_FSIZE, &limited);
    std::unique_ptr<ServerProcess> server;
    try {
        server = std::make_unique<ServerProcess>(binary, dataDir, extraArgs);
    } catch (...) {
        ::setrlimit(RLIMIT_FSIZE, &saved);
        ::signal(SIGXFSZ, previous);
        throw;
    }
    ::setrlimit(RLIMIT_FSIZE, &saved);
    ::signal(SIGXFSZ, previous);
    return server;
}

std::string Reply::header(const std::string& name) const {
    auto it = headers.find(name);
    return it == headers.end() ? "" : it->second;
}

namespace {

Reply toReply(const httplib::Result& result) {
    Reply r;
    if (!result) throw std::runtime_error("request failed: " + httplib::to_string(result.error()));
    r.status = result->status;
    r.raw = result->body;
    r.headers = result->headers;
    r.body = nlohmann::json::parse(result->body, nullptr, false);
    if (r.body.is_discarded()) r.body = nullptr;
    return r;
}

}  // namespace

Reply get(httplib::Client& client, const std::string& path) { return toReply(client.Get(path)); }

Reply postJson(httplib::Client& client, const std::string& path, const nlohmann::json& body) {
    return toReply(client.Post(path, body.dump(), "application/json"));
}

Reply postRaw(httplib::Client& client, const std::string& path, const std::string& body) {
    return toReply(client.Post(path, body, "text/plain"));
}

Reply remove(httplib::Client& client, const std::string& path) { return toReply(client.Delete(path)); }

ConcurrentReads readAtOnce(const ServerProcess& server, const std::string& path, int readers) {
    std::vector<std::pair<int, std::string>> answers(static_cast<std::size_t>(readers), {-1, ""});  // status, body
    std::atomic<int> ready{0};
    std::vector<std::thread> threads;
    for (int i = 0; i < readers; ++i)
        threads.emplace_back([&, i] {
            auto client = server.client();
            ++ready;
            while (ready < readers) std::this_thread::yield();
            if (const auto result = client.Get(path)) answers[static_cast<std::size_t>(i)] = {result->status, result->body};
        });
    for (std::thread& t : threads) t.join();
    ConcurrentReads reads;
    for (const auto& [status, body] : answers) {
        if (status == 200) {
            ++reads.answered;
            reads.bodies.insert(body);
        } else if (status != 429) {
            ++reads.unexpected;
        }
    }
    return reads;
}

bool isPng(const std::string& bytes) { return bytes.size() > 8 && bytes.compare(0, 8, "\x89PNG\r\n\x1a\n") == 0; }

bool isExr(const std::string& bytes) { return bytes.size() > 4 && bytes.compare(0, 4, "\x76\x2f\x31\x01") == 0; }

nlohmann::json waitForRenderState(httplib::Client& client, const std::string& id, const std::vector<std::string>& states,
                                  double timeoutSeconds) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeoutSeconds);
    nlohmann::json status;
    while (std::chrono::steady_clock::now() < deadline) {
        status = get(client, "/api/renders/" + id).body;
        if (status.is_object() && std::find(states.begin(), states.end(), status.value("state", "")) != states.end())
            return status;
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    return status;
}

namespace {

std::string overridden(const char* variable, const std::string& fallback) {
    const char* other = std::getenv(variable);
    return other && *other ? other : fallback;
}

}  // namespace

std::string binaryUnderTest() { return overridden("LENSLAB_SERVER_BINARY", LENSLAB_BINARY); }

std::string fakeServerUnderTest() { return overridden("LENSLAB_FAKE_SERVER_BINARY", LENSLAB_FAKE_SERVER); }

void writeFakeRendererScene(const std::string& folder) {
    std::ofstream(folder + "/any.pbrt") << "# a scene the fake renderer ignores\nCamera \"realistic\"\nWorldBegin\nWorldEnd\n";
}

namespace {

// The server's flags for a scenes folder, once the fake renderer's scene is written there, then `extraArgs`.
std::vector<std::string> fakeSceneFlags(const TempDir& scenes, const std::vector<std::string>& extraArgs) {
    writeFakeRendererScene(scenes.path());
    std::vector<std::string> flags = {"--scenes", scenes.path()};
    flags.insert(flags.end(), extraArgs.begin(), extraArgs.end());
    return flags;
}

}  // namespace

FakeRenderService::FakeRenderService(const std::vector<std::string>& extraArgs)
    : server(fakeServerUnderTest(), data.path() + "/data", fakeSceneFlags(scenes, extraArgs)) {}

}  // namespace lenslab::test
