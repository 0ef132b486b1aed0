// GET /api/glasses: the glasses a lens may name, by name, catalog, nd and Vd, in search order (the
// catalogs given to lenslab serve, the bundled makers, the uploaded catalogs), so the editor can
// check a glass name and show its figures while it is typed, before asking the server for the lens.
#include "prescription/GlassCatalog.h"
#include "core/HttpReply.h"
#include "routes/ServiceParts.h"

namespace lenslab {

namespace {

std::string glassItems(const std::vector<Medium>& glasses) {
    std::string items;
    for (const Medium& m : glasses)
        items += (items.empty() ? "" : ",") +
                 nlohmann::json{{"name", m.name}, {"catalog", m.catalog}, {"nd", m.nd}, {"vd", m.vd}}.dump(
                     -1, ' ', false, nlohmann::json::error_handler_t::replace);
    return items;
}

}  // namespace

void addGlassRoutes(httplib::Server& server, ServiceParts&) {
    server.Get("/api/glasses", [](const httplib::Request&, httplib::Response& res) {
        static const std::string bundled = glassItems(catalogGlasses());  // 1626 glasses: written once
        std::string items;
        for (const std::string& part : {glassItems(loadedGlasses(CatalogPrecedence::BeforeBundled)), bundled,
                                        glassItems(loadedGlasses(CatalogPrecedence::AfterBundled))})
            if (!part.empty()) items += (items.empty() ? "" : ",") + part;
        res.set_content("{\"glasses\":[" + items + "]}", "application/json");
        // Uploads and deletions of catalogs change the list: asked again each time.
        res.set_header("Cache-Control", "no-cache");
    });
}

}  // namespace lenslab
