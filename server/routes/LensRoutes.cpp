// /api/lenses: list, upload (multipart field "file" or the raw table as the body; parsed in the
// heavy-work pool), one lens's data at an aperture and focus, its table text, deletion of uploads.
#include <limits>

#include "core/HttpError.h"
#include "core/HttpReply.h"
#include "core/Identifiers.h"
#include "LensJson.h"
#include "core/QueryParameters.h"
#include "core/UploadedFile.h"
#include "routes/ServiceParts.h"

namespace lenslab {

namespace {

using nlohmann::json;

json lensSummaryJson(const StoredLens& lens) {
    return {{"id", lens.id},           {"name", lens.name},        {"description", lens.description},
            {"bundled", lens.bundled}, {"efl", lens.efl},          {"fstop_min", lens.fstopMin},
            {"fstop_max", lens.fstopMax}, {"created", lens.bundled ? json(nullptr) : json(lens.created)}};
}

// The `lenslab lens --json` object, with the lens's id and how the service holds it.
json lensDetailJson(const StoredLens& lens, const LensSettings& settings) {
    json body = lensAnalysisJson(analyzeLens(lens.system, settings));
    body["id"] = lens.id;
    body["name"] = lens.name;
    body["description"] = lens.description;
    body["bundled"] = lens.bundled;
    return body;
}

std::optional<TableLayout> layoutParameter(const httplib::Request& req) {
    const auto name = queryText(req, "layout");
    if (!name) return std::nullopt;
    const auto layout = parseLayoutName(*name);
    if (!layout) throw HttpError(400, "layout must be gap-before or gap-after");
    return layout;
}

}  // namespace

std::shared_ptr<const StoredLens> findLens(const ServiceParts& parts, const std::string& id) {
    if (!isSafeIdentifier(id)) throw HttpError(400, "'" + id.substr(0, 80) + "' is not a valid lens id");
    auto lens = parts.lenses.find(id);
    if (!lens) throw HttpError(404, "no lens with id '" + id + "' (see GET /api/lenses)");
    return lens;
}

LensTable storedTable(const StoredLens& lens) {
    LensTable table = readLensTable(lens.path, lens.system.layout);
    table.name = lens.name;
    return table;
}

std::string lensContentKey(const ServiceParts& parts, const StoredLens& lens) {
    return lens.digest + "|" + parts.glassCatalogs.digest();
}

void addLensRoutes(httplib::Server& server, ServiceParts& parts) {
    server.Get("/api/lenses", [&parts](const httplib::Request&, httplib::Response& res) {
        json list = json::array();
        for (const auto& lens : parts.lenses.list()) list.push_back(lensSummaryJson(*lens));
        // Uploads not described yet since the start are left out; "loading" says how many.
        replyJson(res, 200, {{"lenses", list}, {"loading", parts.lenses.counts().waiting}});
    });

    server.Post("/api/lenses", [&parts](const httplib::Request& req, httplib::Response& res) {
        const UploadedFile file = uploadedFile(req, "upload.dat");
        if (file.text.find_first_not_of(" \t\r\n") == std::string::npos) throw HttpError(400, "the lens table is empty");
        parts.quota.checkRoomForWrite();
        const std::optional<TableLayout> layout = layoutParameter(req);
        const auto admission = parts.work.admit(clientOf(req));
        try {
            // Parsing and describing a table of up to --max-body bytes is heavy work.
            const auto [lens, body] = parts.work.run([&] {
                const auto catalogsKept = parts.glassCatalogs.holdCatalogs();
                const auto lens = parts.lenses.add(file.name, file.text, layout);
                return std::make_pair(lens, lensDetailJson(*lens, LensSettings{}));
            });
            res.set_header("Location", "/api/lenses/" + lens->id);
            replyJson(res, 201, body);
        } catch (const LensTableError& e) {
            replyJson(res, 400, {{"error", e.what()}, {"file", e.file()}, {"line", e.line()}, {"problem", e.problem()}});
        } catch (const LensStoreFull& e) {
            throw HttpError(409, e.what());
        }
    });

    server.Get(R"(/api/lenses/([^/]+))", [&parts](const httplib::Request& req, httplib::Response& res) {
        const auto lens = findLens(parts, req.matches[1]);
        replyJson(res, 200, lensDetailJson(*lens, queryLensSettings(req)));
    });

    server.Get(R"(/api/lenses/([^/]+)/table)", [&parts](const httplib::Request& req, httplib::Response& res) {
        const auto lens = findLens(parts, req.matches[1]);
        if (!replyFile(res, lens->path, "text/plain; charset=utf-8"))
            throw HttpError(404, "the table of lens '" + lens->id + "' is no longer on disk");
    });

    server.Delete(R"(/api/lenses/([^/]+))", [&parts](const httplib::Request& req, httplib::Response& res) {
        const std::string id = findLens(parts, req.matches[1])->id;
        // Its renders would fail when they start: the client hears it now instead. Checked with
        // submissions held off, so no render can take the lens between the check and the deletion.
        const auto checkUnused = [&] {
            if (const auto renders = parts.jobs.liveJobsWithLens(id); !renders.empty())
                throw HttpError(409, "lens '" + id + "' is used by " + std::to_string(renders.size()) +
                                         " queued or running render(s) (" + renders.front() +
                                         (renders.size() > 1 ? ", ..." : "") + "); cancel them first (DELETE /api/renders/{id})");
        };
        switch (parts.lenses.remove(id, checkUnused)) {
            case LensStore::Removal::Removed:
                parts.diagrams.forget(id + "|");
                replyJson(res, 200, {{"deleted", id}});
                return;
            case LensStore::Removal::ReadOnly:
                throw HttpError(403, "lens '" + id + "' is bundled with lenslab and cannot be deleted");
            case LensStore::Removal::NotFound:
                throw HttpError(404, "no lens with id '" + id + "'");
        }
    });
}

}  // namespace lenslab
