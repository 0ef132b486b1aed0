// Soak test of `lenslab serve` on loopback: 16 (or CLIENTS) keep-alive clients send a fixed mix of requests for
// a set time (cached and never-seen diagrams, lists, render submissions) while the server's
// resident memory, diagram cache size and data-folder size are sampled every 10 s. Memory must
// level off: a steady climb under the same mix is a leak or unbounded growth. A single kind of
// request instead of the mix tells which kind a climb comes from.
// usage: server_soak [SECONDS (default 1800)] [mixed|hits|misses|sizes|lists|renders] [LENSLAB_BINARY] [CLIENTS (16)]
// ("sizes": never-seen diagrams, each of another size)
// (prints Markdown)
#include <httplib.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <functional>
#include <iostream>
#include <stdexcept>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>
#include <vector>

#include "ServerUnderTest.h"

namespace {

using Clock = std::chrono::steady_clock;
using nlohmann::json;
using namespace lenslab::bench;

constexpr int kSampleSeconds = 10;

enum class Kind { CachedDiagram, NewDiagram, NewSizedDiagram, LensListOrHealth, RenderList, RenderSubmission };

// The mix, chosen by the request's index: 55% cached diagrams (24 parameter sets), 25% diagrams
// never asked before (each one drawn), 10% lens list and health, 5% render list, 5% render
// submissions (202, or 429 when the queue is full).
Kind mixedKind(long i) {
    const int slot = static_cast<int>(i % 20);
    if (slot <= 10) return Kind::CachedDiagram;
    if (slot <= 15) return Kind::NewDiagram;
    if (slot <= 17) return Kind::LensListOrHealth;
    return slot == 18 ? Kind::RenderList : Kind::RenderSubmission;
}

// "mixed" or one kind for every request; "lists" alternates the three listings.
std::function<Kind(long)> parseMix(const std::string& name) {
    if (name == "mixed") return mixedKind;
    if (name == "hits") return [](long) { return Kind::CachedDiagram; };
    if (name == "misses") return [](long) { return Kind::NewDiagram; };
    if (name == "sizes") return [](long) { return Kind::NewSizedDiagram; };
    if (name == "lists") return [](long i) { return i % 3 == 2 ? Kind::RenderList : Kind::LensListOrHealth; };
    if (name == "renders") return [](long) { return Kind::RenderSubmission; };
    throw std::invalid_argument("unknown mix '" + name + "': mixed, hits, misses, sizes, lists or renders");
}

struct Counters {
    std::atomic<long> requests{0}, errors{0}, drawn{0}, renders{0};
};

void oneRequest(httplib::Client& client, int clientIndex, long i, Kind kind, Counters& counters) {
    static const std::vector<std::string> lenses = {"dgauss.50mm", "wide.22mm", "telephoto.250mm", "fisheye.10mm"};
    static const std::vector<std::string> modes = {"exact", "thick", "overlay"};
    const auto send = [&]() -> httplib::Result {
        switch (kind) {
            case Kind::CachedDiagram: {
                const long k = (clientIndex * 7 + i) % 24;
                return client.Get("/api/lenses/" + lenses[k % 4] + "/diagram.png?size=800x400&mode=" + modes[(k / 4) % 3]);
            }
            case Kind::NewDiagram: {
                const long unique = ++counters.drawn;
                return client.Get("/api/lenses/" + lenses[unique % 4] + "/diagram.png?size=800x400&mode=" +
                                  modes[unique % 3] + "&focus=" + std::to_string(1000 + unique));
            }
            case Kind::NewSizedDiagram: {  // never asked before, each of its own size (issue 23)
                const long unique = ++counters.drawn;
                const std::string size = std::to_string(320 + unique * 37 % 2081) + "x" + std::to_string(200 + unique * 53 % 1401);
                return client.Get("/api/lenses/" + lenses[unique % 4] + "/diagram.png?size=" + size + "&mode=" +
                                  modes[unique % 3] + "&focus=" + std::to_string(1000 + unique));
            }
            case Kind::LensListOrHealth: return client.Get(i % 2 == 0 ? "/api/lenses" : "/api/health");
            case Kind::RenderList: return client.Get("/api/renders");
            case Kind::RenderSubmission: break;
        }
        ++counters.renders;
        return client.Post("/api/renders", json{{"lens", "dgauss.50mm"}, {"spp", 4}, {"width", 64}, {"height", 48}}.dump(),
                           "application/json");
    };
    const httplib::Result r = send();
    ++counters.requests;
    if (!r || r->status >= 500) ++counters.errors;
}

std::uintmax_t folderBytes(const std::string& folder) {
    std::uintmax_t total = 0;
    std::error_code error;
    for (auto it = std::filesystem::recursive_directory_iterator(folder, error);
         !error && it != std::filesystem::recursive_directory_iterator(); it.increment(error))
        if (it->is_regular_file(error)) total += it->file_size(error);
    return total;
}

}  // namespace

int main(int argc, char** argv) {
    const int seconds = argc > 1 ? std::stoi(argv[1]) : 1800;
    const auto kindOf = parseMix(argc > 2 ? argv[2] : "mixed");
    const std::string binary = argc > 3 ? argv[3] : LENSLAB_BINARY;
    const int clientCount = argc > 4 ? std::stoi(argv[4]) : 16;
    const ServerUnderTest server = startServer(binary, {"--renders", "1", "--max-queue", "8", "--keep-gb", "0.1"});
    Counters counters;
    std::atomic<bool> stop{false};
    std::vector<std::thread> clients;
    for (int c = 0; c < clientCount; ++c)
        clients.emplace_back([&, c] {
            httplib::Client client("127.0.0.1", server.port);
            client.set_keep_alive(true);
            client.set_tcp_nodelay(true);
            client.set_read_timeout(60);
            for (long i = 0; !stop; ++i) oneRequest(client, c, i, kindOf(i), counters);
        });

    std::cout << "| t s | RSS MiB | requests | req/s since last | errors | diagrams drawn | render submissions | "
                 "cache MiB | data folder MiB |\n|---|---|---|---|---|---|---|---|---|\n";
    httplib::Client probe("127.0.0.1", server.port);
    probe.set_read_timeout(30);
    const auto start = Clock::now();
    long lastRequests = 0;
    for (int t = 0; t <= seconds; t += kSampleSeconds) {
        std::this_thread::sleep_until(start + std::chrono::seconds(t));
        double cacheMiB = -1;
        if (auto health = probe.Get("/api/health"); health && health->status == 200)
            cacheMiB = json::parse(health->body)["diagram_cache"]["bytes"].get<double>() / (1 << 20);
        const long requests = counters.requests;
        std::cout.setf(std::ios::fixed);
        std::cout.precision(1);
        std::cout << "| " << t << " | " << residentMiB(server.pid) << " | " << requests << " | "
                  << (t == 0 ? 0.0 : (requests - lastRequests) / double(kSampleSeconds)) << " | " << counters.errors
                  << " | " << counters.drawn << " | " << counters.renders << " | " << cacheMiB << " | "
                  << folderBytes(server.folder + "/data") / double(1 << 20) << " |" << std::endl;
        lastRequests = requests;
    }
    stop = true;
    for (auto& c : clients) c.join();
    const double idleBefore = residentMiB(server.pid);
    std::this_thread::sleep_for(std::chrono::seconds(30));
    std::cout << "\nAfter the load: RSS " << idleBefore << " MiB; after 30 s idle " << residentMiB(server.pid) << " MiB\n";
    stopServer(server);
    return counters.errors == 0 ? 0 : 1;
}
