// Heavy work and the answers that must not wait for it (issue 32), loopback only:
//   1. start: UPLOADS stored uploads of about 1 MiB (uploaded through the API first, then the
//      server restarted): seconds until it listens, and until every upload is described;
//   2. analyses: CLIENTS clients (each from its own 127.0.0.x address) asking for heavy analyses
//      (16 wavelengths x 16 fields, each distinct) for SECONDS, while one prober asks every 100 ms
//      for /api/health and for an analysis already cached: their latency (median, p99, max) and the
//      analyses' answers (200 / 429 / other).
// usage: server_heavy_work [SECONDS (30)] [CLIENTS (64)] [UPLOADS (500)] [LENSLAB_BINARY]  (prints Markdown)
#include <httplib.h>
#include <signal.h>
#include <sys/wait.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>
#include <vector>

#include "ServerUnderTest.h"

namespace {

using Clock = std::chrono::steady_clock;
using nlohmann::json;
using namespace lenslab::bench;

double secondsSince(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// A table of 1 MiB: 252 faces of glass plates, the stop and a singlet, each row padded to 4 KiB.
std::string megabyteTable(int variant) {
    std::string table;
    for (int row = 0; row < 255; ++row) {
        const std::string line = row < 252 ? (row % 2 ? "0 1 1.0 20" : "0 1 1.5 20")
                                 : row == 252 ? "0 2 0 18"
                                 : row == 253 ? std::to_string(50 + variant % 7) + " 5 1.5 20"
                                              : "-50 45 1.0 20";
        table += line + std::string(4096 - line.size() - 1, ' ') + "\n";
    }
    return table;
}

void startupRow(const std::string& binary, int uploads) {
    ServerUnderTest first = startServer(binary, {});
    httplib::Client c("127.0.0.1", first.port);
    c.set_read_timeout(120);
    int stored = 0;
    for (int i = 0; i < uploads; ++i) {
        const auto r = c.Post("/api/lenses?name=big.dat&layout=gap-after", megabyteTable(i), "text/plain");
        stored += r && r->status == 201;
    }
    // Stopped without removing the folder: the same data, started again.
    const std::string data = first.folder + "/data";
    kill(first.pid, SIGTERM);
    int status = 0;
    waitpid(first.pid, &status, 0);
    const auto start = Clock::now();
    ServerUnderTest again = startServer(binary, {}, data);
    const double listening = secondsSince(start);
    httplib::Client probe("127.0.0.1", again.port);
    probe.set_read_timeout(300);
    double described = listening;
    for (;;) {
        const auto health = probe.Get("/api/health");
        if (!health || health->status != 200) break;
        if (json::parse(health->body).value("lenses_loading", 0) == 0) {
            described = secondsSince(start);
            break;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    std::cout << "| " << stored << " stored uploads of 1 MiB | listening after " << listening << " s | all described after "
              << described << " s |\n";
    stopServer(again);
    std::filesystem::remove_all(first.folder);
}

std::string heavyAnalysis(long unique) {
    std::string wavelengths, fields;
    for (int k = 0; k < 16; ++k) {
        wavelengths += (k ? "," : "") + std::to_string(420 + 20 * k);
        fields += (k ? "," : "") + std::to_string(k / 15.0);
    }
    static const char* lenses[] = {"dgauss.50mm", "wide.22mm", "telephoto.250mm", "fisheye.10mm"};
    return std::string("/api/lenses/") + lenses[unique % 4] + "/analysis?wavelengths=" + wavelengths + "&fields=" + fields +
           "&max_frequency=" + std::to_string(50 + unique);
}

struct Latencies {
    std::vector<double> health, cached;
    int failed = 0;
};

void printLatency(const std::string& what, const std::vector<double>& ms) {
    std::cout << "| " << what << " | " << ms.size() << " | " << percentile(ms, 0.5) << " | " << percentile(ms, 0.99) << " | "
              << percentile(ms, 1.0) << " |\n";
}

void analysesRows(const std::string& binary, int seconds, int clients) {
    ServerUnderTest server = startServer(binary, {});
    const std::string cached = "/api/lenses/dgauss.50mm/analysis?wavelengths=d&fields=0";
    httplib::Client warm("127.0.0.1", server.port);
    warm.set_read_timeout(60);
    warm.Get(cached);
    std::atomic<bool> stop{false};
    std::atomic<long> unique{0}, ok{0}, busy{0}, other{0};
    std::vector<std::thread> threads;
    for (int i = 0; i < clients; ++i)
        threads.emplace_back([&, i] {
            httplib::Client c("127.0.0.1", server.port);
            c.set_socket_options(fromLoopbackAddress(i));
            c.set_read_timeout(600);
            while (!stop) {
                const auto r = c.Get(heavyAnalysis(++unique));
                if (r && r->status == 200) ++ok;
                else if (r && r->status == 429) {
                    ++busy;
                    c.stop();  // idle past the server's keep-alive wait while it waits
                    std::this_thread::sleep_for(std::chrono::seconds(std::max(1, std::atoi(r->get_header_value("Retry-After").c_str()))));
                } else ++other;
            }
        });
    Latencies l;
    httplib::Client probe("127.0.0.1", server.port);
    probe.set_socket_options(fromLoopbackAddress(clients));
    probe.set_keep_alive(true);
    probe.set_read_timeout(60);
    const auto start = Clock::now();
    while (secondsSince(start) < seconds) {
        for (auto* list : {&l.health, &l.cached}) {
            const auto t0 = Clock::now();
            const auto r = probe.Get(list == &l.health ? "/api/health" : cached);
            if (r && r->status == 200) list->push_back(1000 * secondsSince(t0));
            else ++l.failed;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    stop = true;
    const auto health = probe.Get("/api/health");
    kill(server.pid, SIGKILL);  // not waiting for the analyses still running
    for (auto& t : threads) t.join();
    int status = 0;
    waitpid(server.pid, &status, 0);
    std::filesystem::remove_all(server.folder);
    std::cout << "\n" << clients << " clients asking for heavy analyses for " << seconds << " s: " << ok << " answered 200, "
              << busy << " answered 429 (Retry-After), " << other << " other; probes failed: " << l.failed << "\n\n"
              << "| probe, every 100 ms | answers | median ms | p99 ms | max ms |\n|---|---|---|---|---|\n";
    printLatency("`/api/health`", l.health);
    printLatency("a cached analysis", l.cached);
    if (health && health->status == 200) std::cout << "\nServer at the end: `" << json::parse(health->body)["work"].dump() << "`\n";
}

}  // namespace

int main(int argc, char** argv) {
    const int seconds = argc > 1 ? std::stoi(argv[1]) : 30;
    const int clients = argc > 2 ? std::stoi(argv[2]) : 64;
    const int uploads = argc > 3 ? std::stoi(argv[3]) : 500;
    const std::string binary = argc > 4 ? argv[4] : LENSLAB_BINARY;
    std::cout.setf(std::ios::fixed);
    std::cout.precision(2);
    if (uploads > 0) {
        std::cout << "| start | listening | described |\n|---|---|---|\n";
        startupRow(binary, uploads);
    }
    if (clients > 0) analysesRows(binary, seconds, clients);
    return 0;
}
