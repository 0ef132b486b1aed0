#include "core/HttpReply.h"

#include <algorithm>
#include <fstream>
#include <memory>

#include "PublicMessage.h"

namespace lenslab {

namespace {

// Files are sent in pieces of this size, so that a download costs this much memory, not its size;
// shared bytes too, so that each write waits on the client for one piece at most.
constexpr std::size_t kFileChunkBytes = 64 << 10;

}  // namespace

std::string jsonText(const nlohmann::json& body) {
    return body.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

void replyJson(httplib::Response& res, int status, const nlohmann::json& body) {
    res.status = status;
    if (status < 400 || !body.is_object()) return res.set_content(jsonText(body), "application/json");
    nlohmann::json refusal = body;
    for (const char* text : {"error", "problem", "file"})
        if (refusal.contains(text) && refusal[text].is_string()) refusal[text] = publicMessage(refusal[text]);
    res.set_content(jsonText(refusal), "application/json");
}

void replyError(httplib::Response& res, int status, const std::string& message) {
    replyJson(res, status, {{"error", message}});
}

void replyBytes(httplib::Response& res, const std::vector<std::uint8_t>& bytes, const std::string& contentType) {
    res.status = 200;
    res.set_content(reinterpret_cast<const char*>(bytes.data()), bytes.size(), contentType);
}

void replySharedBytes(httplib::Response& res, std::shared_ptr<const std::vector<std::uint8_t>> bytes,
                      const std::string& contentType, std::shared_ptr<void> held) {
    res.status = 200;
    if (bytes->empty()) return res.set_content("", contentType);  // see replyFile
    const std::size_t size = bytes->size();
    res.set_content_provider(size, contentType,
                             [bytes, held](std::size_t offset, std::size_t length, httplib::DataSink& sink) {
                                 const auto* data = reinterpret_cast<const char*>(bytes->data());
                                 return sink.write(data + offset, std::min(length, kFileChunkBytes));
                             });
}

bool replyFile(httplib::Response& res, const std::string& path, const std::string& contentType,
               std::shared_ptr<void> held) {
    // Opened now: a file deleted while it is sent stays readable through this handle.
    auto file = std::make_shared<std::ifstream>(path, std::ios::binary | std::ios::ate);
    if (!*file) return false;
    const std::streamoff size = file->tellg();
    if (size < 0) return false;
    res.status = 200;
    if (size == 0) {
        res.set_content("", contentType);  // cpp-httplib takes a provider of length 0 for one of unknown length
        return true;
    }
    res.set_content_provider(static_cast<std::size_t>(size), contentType,
                             [file, held](std::size_t offset, std::size_t length, httplib::DataSink& sink) {
                                 std::vector<char> chunk(std::min(length, kFileChunkBytes));
                                 file->seekg(static_cast<std::streamoff>(offset));
                                 return file->read(chunk.data(), static_cast<std::streamsize>(chunk.size())) &&
                                        sink.write(chunk.data(), chunk.size());
                             });
    return true;
}

}  // namespace lenslab
