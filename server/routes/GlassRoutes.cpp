// GET /api/glasses: the catalog glasses by name, maker, nd and Vd, so the editor can check a
// glass name and show its figures while it is typed, before asking the server for the lens.
#include "prescription/GlassCatalog.h"
#include "core/HttpReply.h"
#include "routes/ServiceParts.h"

namespace lenslab {

void addGlassRoutes(httplib::Server& server, ServiceParts&) {
    server.Get("/api/glasses", [](const httplib::Request&, httplib::Response& res) {
        static const std::string body = [] {
            nlohmann::json glasses = nlohmann::json::array();
            for (const Medium& m : catalogGlasses())
                glasses.push_back({{"name", m.name}, {"catalog", m.catalog}, {"nd", m.nd}, {"vd", m.vd}});
            return nlohmann::json{{"glasses", glasses}}.dump();
        }();
        res.set_content(body, "application/json");
        res.set_header("Cache-Control", "max-age=3600");
    });
}

}  // namespace lenslab
