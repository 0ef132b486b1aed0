#include "core/JsonBody.h"

#include "core/HttpError.h"

namespace lenslab {

nlohmann::json parseJsonBody(const httplib::Request& req, const std::string& what) {
    try {
        return nlohmann::json::parse(req.body);
    } catch (const nlohmann::json::out_of_range&) {
        throw HttpError(400, what + " holds a number too large for a double (past about 1.8e308)");
    } catch (const nlohmann::json::exception&) {
        throw HttpError(400, what + " is not valid JSON");
    }
}

}  // namespace lenslab
