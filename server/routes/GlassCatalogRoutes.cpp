// /api/glass-catalogs: Zemax .agf glass catalogs uploaded (multipart field "file" or the file as the
// body; parsed in the heavy-work pool), listed, shown glass by glass, and deleted when no stored
// lens takes a glass from them (storage/GlassCatalogStore.h says why).
#include <algorithm>

#include "core/HttpError.h"
#include "core/HttpReply.h"
#include "core/Identifiers.h"
#include "core/PrintableAscii.h"
#include "core/UploadedFile.h"
#include "prescription/GlassCatalog.h"
#include "prescription/LensTable.h"
#include "routes/ServiceParts.h"
#include "storage/LensStore.h"

namespace lenslab {

namespace {

using nlohmann::json;

using ShadowedNames = std::map<std::string, std::vector<std::string>>;  // shadowedGlassNames()

const std::vector<std::string>& shadowedIn(const ShadowedNames& shadowed, const StoredGlassCatalog& catalog) {
    static const std::vector<std::string> none;
    const auto it = shadowed.find(catalog.name);
    return it == shadowed.end() ? none : it->second;
}

json catalogSummaryJson(const StoredGlassCatalog& catalog, const ShadowedNames& shadowed) {
    std::vector<int> formulas = catalog.formulaNumbers;
    std::sort(formulas.begin(), formulas.end());
    formulas.erase(std::unique(formulas.begin(), formulas.end()), formulas.end());
    return {{"id", catalog.id},
            {"name", catalog.name},
            {"file_name", catalog.fileName},
            {"glass_count", catalog.glasses.size()},
            {"formulas", formulas},
            {"shadowed_count", shadowedIn(shadowed, catalog).size()},
            {"created", catalog.created}};
}

// Each glass with the maker's nd and Vd (the NM line) and those its formula gives, which a
// mistyped coefficient makes differ; `shadowed`: a lens naming it gets another catalog's glass.
json catalogDetailJson(const StoredGlassCatalog& catalog) {
    const ShadowedNames all = shadowedGlassNames();
    json body = catalogSummaryJson(catalog, all);
    const std::vector<std::string>& shadowed = shadowedIn(all, catalog);
    json glasses = json::array();
    for (std::size_t i = 0; i < catalog.glasses.size(); ++i) {
        const Medium& glass = catalog.glasses[i];
        glasses.push_back({{"name", glass.name},
                           {"formula", catalog.formulaNumbers[i]},
                           {"nd", glass.nd},
                           {"vd", glass.vd},
                           {"nd_formula", refractiveIndex(glass, kWavelengthD)},
                           {"vd_formula", abbeNumber(glass)},
                           {"min_nm", glass.minNm},
                           {"max_nm", glass.maxNm},
                           {"shadowed", std::find(shadowed.begin(), shadowed.end(), glass.name) != shadowed.end()}});
    }
    body["glasses"] = glasses;
    return body;
}

std::shared_ptr<const StoredGlassCatalog> findCatalog(const ServiceParts& parts, const std::string& id) {
    if (!isSafeIdentifier(id)) throw HttpError(400, "'" + id.substr(0, 80) + "' is not a valid glass catalog id");
    auto catalog = parts.glassCatalogs.find(id);
    if (!catalog) throw HttpError(404, "no glass catalog with id '" + id + "' (see GET /api/glass-catalogs)");
    return catalog;
}

// The stored lenses with a surface in one of the catalog's glasses.
std::vector<std::string> lensesUsing(const LensStore& lenses, const std::string& catalogName) {
    return lenses.lensesWhere([&](const StoredLens& lens) {
        return std::any_of(lens.system.surfaces.begin(), lens.system.surfaces.end(),
                           [&](const Surface& s) { return s.mediumAfter.catalog == catalogName; });
    });
}

}  // namespace

void addGlassCatalogRoutes(httplib::Server& server, ServiceParts& parts) {
    server.Get("/api/glass-catalogs", [&parts](const httplib::Request&, httplib::Response& res) {
        json list = json::array();
        const ShadowedNames shadowed = shadowedGlassNames();
        for (const auto& catalog : parts.glassCatalogs.list()) list.push_back(catalogSummaryJson(*catalog, shadowed));
        replyJson(res, 200, {{"catalogs", list}});
    });

    server.Post("/api/glass-catalogs", [&parts](const httplib::Request& req, httplib::Response& res) {
        const UploadedFile file = uploadedFile(req, "upload.agf");
        if (file.text.find_first_not_of(" \t\r\n") == std::string::npos) throw HttpError(400, "the glass catalog is empty");
        // The catalog is named by its file name (without .agf), which lenses' GCAT lines and messages repeat.
        if (const std::string name = uploadDisplayName(file.name, "upload.agf"); !isPrintableAscii(name))
            throw HttpError(400, "the glass catalog's file name '" + name + "' has characters other than printable ASCII "
                                 "(letters, digits, punctuation, spaces): its name could pass for another catalog's");
        parts.quota.checkRoomForWrite();
        const auto admission = parts.work.admit(clientOf(req));
        try {
            const auto [catalog, body] = parts.work.run([&] {
                const auto catalog = parts.glassCatalogs.add(file.name, file.text);
                return std::make_pair(catalog, catalogSummaryJson(*catalog, shadowedGlassNames()));
            });
            res.set_header("Location", "/api/glass-catalogs/" + catalog->id);
            replyJson(res, 201, body);
        } catch (const LensTableError& e) {
            replyJson(res, 422, {{"error", e.what()}, {"file", e.file()}, {"line", e.line()}, {"problem", e.problem()}});
        }
    });

    server.Get(R"(/api/glass-catalogs/([^/]+))", [&parts](const httplib::Request& req, httplib::Response& res) {
        // 20,000 glasses are megabytes of JSON: built once per state of the catalogs, in the pool,
        // not per reader (24 readers took 680 MB).
        const std::string catalogsState = parts.glassCatalogs.digest();
        const auto catalog = findCatalog(parts, req.matches[1]);
        const std::string key = "glass-catalog|" + catalog->id + "|" + catalogsState;
        const auto answer = parts.work.cachedOrComputed(parts.analyses, key, clientOf(req),
                                                        [&] { return textBytes(jsonText(catalogDetailJson(*catalog))); });
        replyBytes(res, *answer, "application/json");
    });

    server.Delete(R"(/api/glass-catalogs/([^/]+))", [&parts](const httplib::Request& req, httplib::Response& res) {
        const std::string id = findCatalog(parts, req.matches[1])->id;
        const auto admission = parts.work.admit(clientOf(req));
        // Uploads not described since the start are described to be checked: heavy work.
        const bool removed = parts.work.run(
            [&] { return parts.glassCatalogs.remove(id, [&](const std::string& name) { return lensesUsing(parts.lenses, name); }); });
        if (!removed) throw HttpError(404, "no glass catalog with id '" + id + "'");
        replyJson(res, 200, {{"deleted", id}});
    });
}

}  // namespace lenslab
