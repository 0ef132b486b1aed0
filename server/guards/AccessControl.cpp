#include "guards/AccessControl.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <fstream>
#include <random>
#include <stdexcept>

#include "core/CommaList.h"

namespace lenslab {

namespace {

bool isRead(const httplib::Request& req) {
    return req.method == "GET" || req.method == "HEAD" || req.method == "OPTIONS";
}

bool endsWith(const std::string& text, const std::string& end) {
    return text.size() >= end.size() && text.compare(text.size() - end.size(), end.size(), end) == 0;
}

// Writes, and the reads computed in the heavy-work pool: a lens's analyses and its diagram.
bool spendsCpu(const httplib::Request& req) {
    if (!isRead(req)) return true;
    return req.method != "OPTIONS" && req.path.rfind("/api/lenses/", 0) == 0 &&
           (endsWith(req.path, "/analysis") || endsWith(req.path, "/ghosts") || endsWith(req.path, "/diagram.png"));
}

// Compares in time independent of where the strings differ, so the token cannot be guessed byte
// by byte from answer times.
bool sameSecret(const std::string& a, const std::string& b) {
    if (a.size() != b.size()) return false;
    unsigned char difference = 0;
    for (std::size_t i = 0; i < a.size(); ++i) difference |= static_cast<unsigned char>(a[i] ^ b[i]);
    return difference == 0;
}

bool originAllowed(const httplib::Request& req, const AccessPolicy& policy) {
    const std::string origin = req.get_header_value("Origin");
    if (origin.empty()) return true;  // not sent by a browser on another site's behalf
    return origin == "http://" + req.get_header_value("Host") || isListedOrigin(origin, policy);
}

std::string randomToken() {
    std::ifstream urandom("/dev/urandom", std::ios::binary);
    unsigned char bytes[24];
    if (!urandom.read(reinterpret_cast<char*>(bytes), sizeof bytes))
        throw std::runtime_error("cannot read /dev/urandom to make an API token");
    static const char digits[] = "0123456789abcdef";
    std::string token;
    for (unsigned char b : bytes) {
        token += digits[b >> 4];
        token += digits[b & 15];
    }
    return token;
}

}  // namespace

bool isListedOrigin(const std::string& origin, const AccessPolicy& policy) {
    for (const std::string& entry : commaListEntries(policy.allowedOrigins))
        if (entry == origin) return true;
    return false;
}

std::optional<HttpError> refuseAccess(const httplib::Request& req, const AccessPolicy& policy) {
    if (!originAllowed(req, policy))
        return HttpError(403, "cross-origin requests are refused (origin " + req.get_header_value("Origin").substr(0, 100) +
                                  "); start the server with --allow-origin to allow one");
    if (policy.token.empty() || (!spendsCpu(req) && !policy.privateReads)) return std::nullopt;
    const std::string authorization = req.get_header_value("Authorization");
    const std::string prefix = "Bearer ";
    if (authorization.rfind(prefix, 0) != 0 || !sameSecret(authorization.substr(prefix.size()), policy.token))
        return HttpError(401, "this request needs the server's API token: send 'Authorization: Bearer TOKEN' "
                              "(the token is in the file given to lenslab serve --token-file)");
    return std::nullopt;
}

std::string loadOrCreateToken(const std::string& path, bool& created) {
    created = false;
    if (std::ifstream in(path); in) {
        std::string line;
        std::getline(in, line);
        // Editors add trailing spaces and CRs, and clients trim header values: the token is the line trimmed.
        const std::string blanks = " \t\r\n\v\f";
        const std::size_t first = line.find_first_not_of(blanks), last = line.find_last_not_of(blanks);
        const std::string token = first == std::string::npos ? "" : line.substr(first, last - first + 1);
        if (token.size() < 16) throw std::runtime_error("the token file '" + path + "' holds no token of 16+ characters");
        for (unsigned char c : token)
            if (c <= ' ' || c == 0x7f)
                throw std::runtime_error("the token in '" + path + "' contains a space or control character; "
                                         "a token is one word of printable characters");
        return token;
    }
    const std::string token = randomToken();
    const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL, 0600);
    const std::string line = token + "\n";
    const bool written = fd >= 0 && ::write(fd, line.data(), line.size()) == static_cast<ssize_t>(line.size());
    if (fd >= 0) ::close(fd);
    if (!written) throw std::runtime_error("cannot write the token file '" + path + "'");
    created = true;
    return token;
}

bool isLoopbackHost(const std::string& host) {
    return host == "localhost" || host == "::1" || host.rfind("127.", 0) == 0;
}

}  // namespace lenslab
