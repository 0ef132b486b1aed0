// Soak test of `lenslab serve` on loopback: groups of keep-alive clients, each client from its own
// 127.0.0.x address, send a fixed mix of requests for a set time while the server's resident memory,
// cache sizes and data-folder size are sampled every 10 s and a prober asks for /api/health every
// 100 ms (its median latency per window). Memory must level off: a steady climb under the same mix
// is a leak or unbounded growth. Answers 5xx (or none) are counted as errors; 429 (a full queue or
// pool, with Retry-After) as refusals, after which the client waits as told.
// usage: server_soak [SECONDS (1800)] [GROUPS (mixed:16)] [LENSLAB_BINARY]
// GROUPS: comma-separated MIX:CLIENTS, all at once. MIX: mixed (diagrams, lists, renders), hits,
// misses, sizes (never-seen diagrams, each of another size), lists, renders, downloads (a 1920x1920
// render's image.exr and /pixels, over and over), analyses (analyses and editor previews, half of
// them cached). Issue 32's soak: server_soak 1800 sizes:8,downloads:16,analyses:16
// (prints Markdown)
#include <httplib.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <filesystem>
#include <functional>
#include <iostream>
#include <mutex>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "ServerUnderTest.h"

namespace {

using Clock = std::chrono::steady_clock;
using nlohmann::json;
using namespace lenslab::bench;

constexpr int kSampleSeconds = 10;

enum class Kind {
    CachedDiagram, NewDiagram, NewSizedDiagram, LensListOrHealth, RenderList, RenderSubmission, Download, Analysis, Preview
};

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

// A mix by name: "mixed" or one kind for every request; "lists" alternates the three listings,
// "analyses" analyses and previews.
std::function<Kind(long)> parseMix(const std::string& name) {
    if (name == "mixed") return mixedKind;
    if (name == "hits") return [](long) { return Kind::CachedDiagram; };
    if (name == "misses") return [](long) { return Kind::NewDiagram; };
    if (name == "sizes") return [](long) { return Kind::NewSizedDiagram; };
    if (name == "lists") return [](long i) { return i % 3 == 2 ? Kind::RenderList : Kind::LensListOrHealth; };
    if (name == "renders") return [](long) { return Kind::RenderSubmission; };
    if (name == "downloads") return [](long) { return Kind::Download; };
    if (name == "analyses") return [](long i) { return i % 2 ? Kind::Preview : Kind::Analysis; };
    throw std::invalid_argument("unknown mix '" + name + "': mixed, hits, misses, sizes, lists, renders, downloads or analyses");
}

struct Group {
    std::string mix;
    int clients;
    std::function<Kind(long)> kindOf;
};

// "sizes:8,downloads:16" -> its groups.
std::vector<Group> parseGroups(const std::string& text) {
    std::vector<Group> groups;
    std::stringstream in(text);
    for (std::string item; std::getline(in, item, ',');) {
        const std::size_t colon = item.find(':');
        const std::string mix = item.substr(0, colon);
        groups.push_back({mix, colon == std::string::npos ? 16 : std::stoi(item.substr(colon + 1)), parseMix(mix)});
    }
    return groups;
}

struct Counters {
    std::atomic<long> requests{0}, errors{0}, refused{0}, drawn{0}, renders{0}, analyses{0};
};

// What every client shares: the rows previews edit, the finished render downloads read.
struct Shared {
    json previewRows;
    std::string downloadRender;
};

httplib::Result send(httplib::Client& client, int clientIndex, long i, Kind kind, Counters& counters, const Shared& shared) {
    static const std::vector<std::string> lenses = {"dgauss.50mm", "wide.22mm", "telephoto.250mm", "fisheye.10mm"};
    static const std::vector<std::string> modes = {"exact", "thick", "overlay"};
    switch (kind) {
        case Kind::CachedDiagram: {
            const long k = (clientIndex * 7 + i) % 24;
            return client.Get("/api/lenses/" + lenses[k % 4] + "/diagram.png?size=800x400&mode=" + modes[(k / 4) % 3]);
        }
        case Kind::NewDiagram: {
            const long unique = ++counters.drawn;
            return client.Get("/api/lenses/" + lenses[unique % 4] + "/diagram.png?size=800x400&mode=" + modes[unique % 3] +
                              "&focus=" + std::to_string(1000 + unique));
        }
        case Kind::NewSizedDiagram: {  // never asked before, each of its own size (issue 23)
            const long unique = ++counters.drawn;
            const std::string size = std::to_string(320 + unique * 37 % 2081) + "x" + std::to_string(200 + unique * 53 % 1401);
            return client.Get("/api/lenses/" + lenses[unique % 4] + "/diagram.png?size=" + size + "&mode=" +
                              modes[unique % 3] + "&focus=" + std::to_string(1000 + unique));
        }
        case Kind::LensListOrHealth: return client.Get(i % 2 == 0 ? "/api/lenses" : "/api/health");
        case Kind::RenderList: return client.Get("/api/renders");
        case Kind::RenderSubmission:
            ++counters.renders;
            return client.Post("/api/renders", json{{"lens", "dgauss.50mm"}, {"spp", 4}, {"width", 64}, {"height", 48}}.dump(),
                               "application/json");
        case Kind::Download:  // streamed: the body is dropped as it arrives
            return client.Get("/api/renders/" + shared.downloadRender + (clientIndex % 2 ? "/pixels" : "/image.exr"),
                              [](const char*, std::size_t) { return true; });
        case Kind::Analysis: {  // every other one of 12 repeated parameter sets (cached), the rest new
            const long unique = i % 4 == 0 ? (clientIndex + i) % 12 : 100 + ++counters.analyses;
            return client.Get("/api/lenses/" + lenses[unique % 4] + "/analysis?wavelengths=F,d,C&fields=0,0.5,0.7,1&fstop=" +
                              std::to_string(8 + unique % 5) + "&focus=" + std::to_string(2000 + unique));
        }
        case Kind::Preview: {  // likewise: every other one an edit seen before
            json body = shared.previewRows;
            const long unique = i % 4 == 1 ? (clientIndex + i) % 12 : 100 + ++counters.analyses;
            body["rows"][0]["radius"] = body["rows"][0]["radius"].get<double>() * (1 + 1e-4 * unique);
            return client.Post("/api/prescriptions/preview", body.dump(), "application/json");
        }
    }
    throw std::logic_error("unknown kind");
}

void oneRequest(httplib::Client& client, int clientIndex, long i, Kind kind, Counters& counters, const Shared& shared) {
    const httplib::Result r = send(client, clientIndex, i, kind, counters, shared);
    ++counters.requests;
    if (!r || r->status >= 500) {
        if (++counters.errors <= 20)  // what they were, on standard error
            std::cerr << "error: request kind " << static_cast<int>(kind) << ": "
                      << (r ? std::to_string(r->status) + " " + r->body.substr(0, 200) : httplib::to_string(r.error())) << "\n";
    } else if (r->status == 429) {
        ++counters.refused;
        client.stop();  // a connection idle past the server's keep-alive wait may be closed under the next request
        std::this_thread::sleep_for(std::chrono::seconds(std::max(1, std::atoi(r->get_header_value("Retry-After").c_str()))));
    }
}

std::uintmax_t folderBytes(const std::string& folder) {
    std::uintmax_t total = 0;
    std::error_code error;
    for (auto it = std::filesystem::recursive_directory_iterator(folder, error);
         !error && it != std::filesystem::recursive_directory_iterator(); it.increment(error))
        if (it->is_regular_file(error)) total += it->file_size(error);
    return total;
}

// A finished 1920x1920 render for the downloads (thick lens, 1 spp: seconds).
std::string finishedRender(int port) {
    httplib::Client c("127.0.0.1", port);
    const auto r = c.Post("/api/renders", json{{"spp", 1}, {"width", 1920}, {"height", 1920}, {"mode", "thick"}}.dump(),
                          "application/json");
    if (!r || r->status != 202) throw std::runtime_error("the download render was not accepted");
    const std::string id = json::parse(r->body)["id"];
    for (;;) {
        const auto status = c.Get("/api/renders/" + id);
        if (status && json::parse(status->body)["state"] == "done") return id;
        std::this_thread::sleep_for(std::chrono::seconds(1));
    }
}

// /api/health every 100 ms on its own connection; the latencies of the current window.
class HealthProber {
public:
    HealthProber(int port, int addressIndex) : thread_([this, port, addressIndex] {
          httplib::Client c("127.0.0.1", port);
          c.set_socket_options(fromLoopbackAddress(addressIndex));
          c.set_keep_alive(true);
          c.set_read_timeout(60);
          while (!stop_) {
              const auto t0 = Clock::now();
              const auto r = c.Get("/api/health");
              const double ms = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
              {
                  std::lock_guard<std::mutex> lock(mutex_);
                  if (r && r->status == 200) {
                      window_.push_back(ms);
                      all_.push_back(ms);
                  } else {
                      ++failed_;
                  }
              }
              std::this_thread::sleep_for(std::chrono::milliseconds(100));
          }
      }) {}
    ~HealthProber() {
        stop_ = true;
        thread_.join();
    }
    double windowMedian() {
        std::lock_guard<std::mutex> lock(mutex_);
        const double median = percentile(window_, 0.5);
        window_.clear();
        return median;
    }
    std::vector<double> all() {
        std::lock_guard<std::mutex> lock(mutex_);
        return all_;
    }
    long failed() {
        std::lock_guard<std::mutex> lock(mutex_);
        return failed_;
    }

private:
    std::atomic<bool> stop_{false};
    std::mutex mutex_;
    std::vector<double> window_, all_;
    long failed_ = 0;
    std::thread thread_;
};

}  // namespace

int main(int argc, char** argv) {
    const int seconds = argc > 1 ? std::stoi(argv[1]) : 1800;
    const std::vector<Group> groups = parseGroups(argc > 2 ? argv[2] : "mixed:16");
    const std::string binary = argc > 3 ? argv[3] : LENSLAB_BINARY;
    const ServerUnderTest server = startServer(binary, {"--renders", "1", "--max-queue", "8", "--keep-gb", "0.1"});
    Shared shared;
    {
        httplib::Client c("127.0.0.1", server.port);
        shared.previewRows = json::parse(c.Get("/api/lenses/dgauss.50mm/prescription")->body);
    }
    for (const Group& g : groups)
        if (g.mix == "downloads") shared.downloadRender = finishedRender(server.port);
    Counters counters;
    std::atomic<bool> stop{false};
    std::vector<std::thread> clients;
    int address = 0;
    for (const Group& g : groups)
        for (int c = 0; c < g.clients; ++c, ++address)
            clients.emplace_back([&, c, address, kindOf = g.kindOf] {
                httplib::Client client("127.0.0.1", server.port);
                client.set_socket_options(fromLoopbackAddress(address));
                client.set_keep_alive(true);
                client.set_tcp_nodelay(true);
                client.set_read_timeout(120);
                for (long i = 0; !stop; ++i) oneRequest(client, c, i, kindOf(i), counters, shared);
            });
    HealthProber prober(server.port, address);

    std::cout << "| t s | RSS MiB | requests | req/s since last | errors (5xx, none) | 429 | health median ms | "
                 "diagrams drawn | render submissions | diagram cache MiB | analysis cache MiB | data folder MiB |\n"
                 "|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    httplib::Client probe("127.0.0.1", server.port);
    probe.set_read_timeout(60);
    const auto start = Clock::now();
    long lastRequests = 0;
    for (int t = 0; t <= seconds; t += kSampleSeconds) {
        std::this_thread::sleep_until(start + std::chrono::seconds(t));
        double diagramMiB = -1, analysisMiB = -1;
        if (auto health = probe.Get("/api/health"); health && health->status == 200) {
            const json h = json::parse(health->body);
            diagramMiB = h["diagram_cache"]["bytes"].get<double>() / (1 << 20);
            if (h.contains("analysis_cache")) analysisMiB = h["analysis_cache"]["bytes"].get<double>() / (1 << 20);
        }
        const long requests = counters.requests;
        std::cout.setf(std::ios::fixed);
        std::cout.precision(1);
        std::cout << "| " << t << " | " << residentMiB(server.pid) << " | " << requests << " | "
                  << (t == 0 ? 0.0 : (requests - lastRequests) / double(kSampleSeconds)) << " | " << counters.errors << " | "
                  << counters.refused << " | " << prober.windowMedian() << " | " << counters.drawn << " | " << counters.renders
                  << " | " << diagramMiB << " | " << analysisMiB << " | " << folderBytes(server.folder + "/data") / double(1 << 20)
                  << " |" << std::endl;
        lastRequests = requests;
    }
    stop = true;
    for (auto& c : clients) c.join();
    const std::vector<double> health = prober.all();
    std::cout << "\n/api/health every 100 ms: " << health.size() << " answers, median " << percentile(health, 0.5)
              << " ms, p99 " << percentile(health, 0.99) << " ms, max " << percentile(health, 1.0) << " ms, "
              << prober.failed() << " failed\n";
    const double idleBefore = residentMiB(server.pid);
    std::this_thread::sleep_for(std::chrono::seconds(30));
    std::cout << "After the load: RSS " << idleBefore << " MiB; after 30 s idle " << residentMiB(server.pid) << " MiB; "
              << counters.errors << " errors (5xx or no answer) of " << counters.requests << " requests\n";
    stopServer(server);
    return counters.errors == 0 ? 0 : 1;
}
