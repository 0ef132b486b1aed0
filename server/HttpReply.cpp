#include "HttpReply.h"

#include "AtomicFile.h"

namespace lenslab {

void replyJson(httplib::Response& res, int status, const nlohmann::json& body) {
    res.status = status;
    res.set_content(body.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace), "application/json");
}

void replyError(httplib::Response& res, int status, const std::string& message) {
    replyJson(res, status, {{"error", message}});
}

void replyBytes(httplib::Response& res, const std::vector<std::uint8_t>& bytes, const std::string& contentType) {
    res.status = 200;
    res.set_content(reinterpret_cast<const char*>(bytes.data()), bytes.size(), contentType);
}

bool replyFile(httplib::Response& res, const std::string& path, const std::string& contentType) {
    try {
        res.set_content(readWholeFile(path), contentType);
        res.status = 200;
        return true;
    } catch (const std::exception&) {
        return false;
    }
}

}  // namespace lenslab
