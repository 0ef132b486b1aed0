#pragma once
// How handlers answer: JSON bodies, {"error": ...} bodies, binary files.
#include <httplib.h>
#include <nlohmann/json.hpp>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace lenslab {

// A refusal's (status 400 on) texts "error", "problem" and "file" pass through publicMessage: no
// server path, no long echo of the input.
void replyJson(httplib::Response& res, int status, const nlohmann::json& body);
// A JSON answer's text as replyJson sends it (invalid UTF-8 replaced), for answers cached as text.
std::string jsonText(const nlohmann::json& body);
void replyError(httplib::Response& res, int status, const std::string& message);
void replyBytes(httplib::Response& res, const std::vector<std::uint8_t>& bytes, const std::string& contentType);
// Sends bytes that other readers share (a cached image) from where they lie, without a copy per answer.
// `held` (a download slot) is kept until the answer has been sent.
void replySharedBytes(httplib::Response& res, std::shared_ptr<const std::vector<std::uint8_t>> bytes,
                      const std::string& contentType, std::shared_ptr<void> held = nullptr);
// Sends a file, read in pieces as the client takes them (byte ranges too). False if unreadable.
bool replyFile(httplib::Response& res, const std::string& path, const std::string& contentType,
               std::shared_ptr<void> held = nullptr);

}  // namespace lenslab
