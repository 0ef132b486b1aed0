// Load test of `lenslab serve`, loopback only and bounded (fixed numbers of requests):
//   1. diagrams: 16 concurrent keep-alive clients, each a fixed number of requests over a set of
//      parameter combinations (first drawings, then cache hits); requests/s, p50/p99, errors;
//   2. the same with every request distinct (every one drawn);
//   3. a full render queue: submissions past --max-queue get 429 while the API stays responsive.
//   Each diagram and submission run is made twice: alone, and with 40 slowloris connections open.
// usage: server_load [LENSLAB_BINARY]   (prints a Markdown summary)
#include <httplib.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "ServerUnderTest.h"
#include "SlowClients.h"

namespace {

using Clock = std::chrono::steady_clock;
using nlohmann::json;
using namespace lenslab::bench;

struct Sample {
    double ms;
    bool ok;
};

using Send = std::function<httplib::Result(httplib::Client&, int, int)>;
using Accept = std::function<bool(const httplib::Response&)>;

bool isPngReply(const httplib::Response& r) { return r.status == 200 && r.body.size() > 8 && r.body.compare(1, 3, "PNG") == 0; }

Send getOf(const std::function<std::string(int, int)>& urlFor) {
    return [urlFor](httplib::Client& client, int c, int i) { return client.Get(urlFor(c, i)); };
}

// `clients` threads, each `perClient` requests send(client, c, i); returns the summary row.
std::string loadRow(const std::string& label, int port, int clients, int perClient, const Send& send,
                    const Accept& accept = isPngReply) {
    std::vector<std::vector<Sample>> samples(clients);
    const auto start = Clock::now();
    std::vector<std::thread> threads;
    for (int c = 0; c < clients; ++c)
        threads.emplace_back([&, c] {
            httplib::Client client("127.0.0.1", port);
            client.set_keep_alive(true);
            client.set_tcp_nodelay(true);
            client.set_read_timeout(30);
            for (int i = 0; i < perClient; ++i) {
                const auto t0 = Clock::now();
                auto r = send(client, c, i);
                const double ms = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
                const bool ok = r && accept(*r);
                samples[c].push_back({ms, ok});
            }
        });
    for (auto& t : threads) t.join();
    const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
    std::vector<double> ms;
    int errors = 0;
    for (const auto& list : samples)
        for (const Sample& s : list) {
            ms.push_back(s.ms);
            errors += s.ok ? 0 : 1;
        }
    std::ostringstream row;
    row.setf(std::ios::fixed);
    row.precision(1);
    row << "| " << label << " | " << clients << " | " << ms.size() << " | " << ms.size() / seconds << " | "
        << percentile(ms, 0.5) << " | " << percentile(ms, 0.99) << " | " << percentile(ms, 1.0) << " | " << errors << " |";
    return row.str();
}

std::string fullQueueReport(const std::string& binary) {
    const int maxQueue = 4;
    const ServerUnderTest s = startServer(binary, {"--max-queue", std::to_string(maxQueue), "--renders", "1", "--max-spp", "4096"});
    httplib::Client c("127.0.0.1", s.port);
    c.set_read_timeout(30);
    const std::string body = json{{"lens", "dgauss.50mm"}, {"spp", 4096}, {"width", 320}, {"height", 240}}.dump();
    std::vector<std::string> ids;
    std::vector<int> statuses;
    std::string refusal;
    std::vector<double> refusalMs;
    for (int i = 0; i < maxQueue + 1 + 20; ++i) {
        const auto t0 = Clock::now();
        auto r = c.Post("/api/renders", body, "application/json");
        const double ms = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
        statuses.push_back(r ? r->status : 0);
        if (r && r->status == 202) ids.push_back(json::parse(r->body)["id"]);
        if (r && r->status == 429) {
            refusal = r->body;
            refusalMs.push_back(ms);
        }
        if (i == 0) std::this_thread::sleep_for(std::chrono::milliseconds(300));  // first one starts running
    }
    std::vector<double> healthMs;
    for (int i = 0; i < 200; ++i) {
        const auto t0 = Clock::now();
        auto r = c.Get("/api/health");
        if (r && r->status == 200) healthMs.push_back(std::chrono::duration<double, std::milli>(Clock::now() - t0).count());
    }
    const std::string healthBody = c.Get("/api/health")->body;
    std::vector<int> cancelStatuses;
    for (const std::string& id : ids) cancelStatuses.push_back(c.Delete("/api/renders/" + id)->status);
    int cancelled = 0;
    for (int i = 0; i < 100 && cancelled < static_cast<int>(ids.size()); ++i) {
        cancelled = 0;
        for (const std::string& id : ids)
            cancelled += json::parse(c.Get("/api/renders/" + id)->body)["state"] == "cancelled" ? 1 : 0;
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    stopServer(s);
    const auto count = [&](int code) { return std::count(statuses.begin(), statuses.end(), code); };
    std::ostringstream out;
    out.setf(std::ios::fixed);
    out.precision(2);
    out << "- `--max-queue " << maxQueue << " --renders 1`, " << statuses.size() << " submissions of a 320x240, 4096 spp render: "
        << count(202) << " accepted (202: 1 running + " << maxQueue << " queued), " << count(429) << " refused with 429, "
        << (statuses.size() - count(202) - count(429)) << " other\n";
    out << "- 429 answer (" << percentile(refusalMs, 0.5) << " ms median): `" << refusal << "`\n";
    out << "- `GET /api/health` while the queue is full and a render runs: " << healthMs.size() << "/200 answered, p50 "
        << percentile(healthMs, 0.5) << " ms, p99 " << percentile(healthMs, 0.99) << " ms: `" << healthBody << "`\n";
    out << "- cancelling all " << ids.size() << " jobs: statuses";
    for (int st : cancelStatuses) out << " " << st;
    out << "; " << cancelled << "/" << ids.size() << " reached `cancelled`\n";
    return out.str();
}

}  // namespace

int main(int argc, char** argv) {
    const std::string binary = argc > 1 ? argv[1] : LENSLAB_BINARY;
    std::cout << "## Diagrams (GET /api/lenses/{id}/diagram.png, 800x400)\n\n"
              << "| workload | clients | requests | requests/s | p50 ms | p99 ms | max ms | errors |\n"
              << "|---|---|---|---|---|---|---|---|\n";
    const std::vector<std::string> lenses = {"dgauss.50mm", "wide.22mm", "telephoto.250mm", "fisheye.10mm"};
    const std::vector<std::string> modes = {"exact", "thick", "overlay"};
    const std::vector<std::string> fstops = {"", "&fstop=5.6"};
    const auto mixed = [&](int c, int i) {
        const int k = (c * 7 + i) % 24;
        return "/api/lenses/" + lenses[k % 4] + "/diagram.png?size=800x400&mode=" + modes[(k / 4) % 3] + fstops[k / 12];
    };
    // Each run its own focus range, so that every request of it is drawn.
    const auto distinct = [](int run) {
        return [run](int c, int i) {
            return "/api/lenses/dgauss.50mm/diagram.png?size=800x400&mode=overlay&focus=" +
                   std::to_string(1000 + run * 10000 + c * 100 + i);
        };
    };
    const Send submitRender = [](httplib::Client& client, int, int) {
        return client.Post("/api/renders", json{{"lens", "dgauss.50mm"}, {"spp", 4}, {"width", 64}, {"height", 48}}.dump(),
                           "application/json");
    };
    const Accept acceptedOrQueueFull = [](const httplib::Response& r) { return r.status == 202 || r.status == 429; };
    for (const int slow : {0, 40}) {
        // A 2 s header deadline with slow clients, so that they are cut off (and come back) during the runs.
        const ServerUnderTest s = startServer(binary, {"--max-queue", "8", "--header-timeout", slow > 0 ? "2" : "10"});
        std::unique_ptr<SlowClients> slowClients;
        if (slow > 0) {
            slowClients = std::make_unique<SlowClients>(s.port, slow);
            std::this_thread::sleep_for(std::chrono::seconds(3));
        }
        const std::string with = slow > 0 ? ", " + std::to_string(slow) + " slowloris connections present" : "";
        std::cout << loadRow("24 parameter sets, repeated (cache hits after the first drawing)" + with, s.port, 16, 250,
                             getOf(mixed)) << "\n";
        std::cout << loadRow("every request distinct (each one drawn)" + with, s.port, 16, 10, getOf(distinct(slow)))
                  << "\n";
        std::cout << loadRow("render submissions, 64x48 (202 accepted or 429 queue full)" + with, s.port, 16, 20,
                             submitRender, acceptedOrQueueFull) << "\n";
        if (slowClients)
            std::cout << "\nSlow connections cut off by the header deadline during the runs: " << slowClients->reconnects()
                      << "\n\n";
        slowClients.reset();
        std::cout << "\nServer after the runs" << with << ": `" << httplib::Client("127.0.0.1", s.port).Get("/api/health")->body
                  << "`, RSS " << residentMiB(s.pid) << " MiB\n\n";
        if (slow == 0)
            std::cout << "| workload | clients | requests | requests/s | p50 ms | p99 ms | max ms | errors |\n"
                      << "|---|---|---|---|---|---|---|---|\n";
        stopServer(s);
    }
    std::cout << "\n## Full render queue\n\n" << fullQueueReport(binary);
    return 0;
}
