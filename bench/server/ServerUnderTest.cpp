#include "ServerUnderTest.h"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <signal.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <thread>

namespace lenslab::bench {

ServerUnderTest startServer(const std::string& binary, const std::vector<std::string>& extra, const std::string& data) {
    ServerUnderTest s;
    char pattern[] = "/tmp/lenslab-load-XXXXXX";
    s.folder = mkdtemp(pattern);
    const std::string log = s.folder + "/server.out";
    std::vector<std::string> args = {binary, "serve", "--port", "0", "--data", data.empty() ? s.folder + "/data" : data,
                                     "--access-log", s.folder + "/access.log"};
    args.insert(args.end(), extra.begin(), extra.end());
    std::cout.flush();
    s.pid = fork();
    if (s.pid == 0) {
        if (!freopen(log.c_str(), "w", stdout) || !freopen(log.c_str(), "a", stderr)) _exit(126);
        std::vector<char*> argv;
        for (auto& a : args) argv.push_back(a.data());
        argv.push_back(nullptr);
        execv(binary.c_str(), argv.data());
        _exit(127);
    }
    const std::regex listening(R"(listening on http://[^:]+:(\d+)/)");
    for (int i = 0; i < 12000; ++i) {
        std::ifstream in(log);
        std::stringstream text;
        text << in.rdbuf();
        std::smatch m;
        const std::string t = text.str();
        if (std::regex_search(t, m, listening)) {
            s.port = std::stoi(m[1]);
            return s;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    throw std::runtime_error("server did not start");
}

void stopServer(const ServerUnderTest& s) {
    kill(s.pid, SIGTERM);
    int status = 0;
    waitpid(s.pid, &status, 0);
    std::filesystem::remove_all(s.folder);
}

double residentMiB(pid_t pid) {
    std::ifstream status("/proc/" + std::to_string(pid) + "/status");
    std::string line;
    while (std::getline(status, line))
        if (line.rfind("VmRSS:", 0) == 0) return std::strtod(line.c_str() + 6, nullptr) / 1024.0;
    return 0;
}

std::function<void(int)> fromLoopbackAddress(int index) {
    return [index](int socket) {
        sockaddr_in address{};
        address.sin_family = AF_INET;
        address.sin_addr.s_addr = htonl((127u << 24) | static_cast<unsigned>(2 + index % 250));
        ::bind(socket, reinterpret_cast<sockaddr*>(&address), sizeof address);
    };
}

double percentile(std::vector<double> v, double p) {
    if (v.empty()) return 0;
    std::sort(v.begin(), v.end());
    return v[std::min(v.size() - 1, static_cast<std::size_t>(p * (v.size() - 1) + 0.5))];
}

}  // namespace lenslab::bench
