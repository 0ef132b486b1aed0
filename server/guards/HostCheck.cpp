#include "guards/HostCheck.h"

#include <arpa/inet.h>

#include <algorithm>
#include <cctype>
#include <sstream>

namespace lenslab {

namespace {

std::string lowerCase(std::string text) {
    std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::tolower(c); });
    return text;
}

// "name:port", "[v6]:port" or either without a port -> the name or address alone.
std::string hostName(const std::string& host) {
    if (!host.empty() && host.front() == '[') return host.substr(1, host.find(']') - 1);
    const std::size_t colon = host.find(':');
    return host.substr(0, colon);
}

// An address needs no name lookup, so it cannot be rebound.
bool isAddress(const std::string& name) {
    unsigned char address[16];
    return inet_pton(AF_INET, name.c_str(), address) == 1 || inet_pton(AF_INET6, name.c_str(), address) == 1;
}

bool isListed(const std::string& name, const std::string& list) {
    std::stringstream entries(list);
    for (std::string entry; std::getline(entries, entry, ',');)
        if (!entry.empty() && lowerCase(entry) == name) return true;
    return false;
}

}  // namespace

std::optional<HttpError> refuseHost(const httplib::Request& req, const std::string& listenHost,
                                    const std::string& allowedHosts) {
    if (!req.has_header("Host")) return std::nullopt;
    const std::string name = lowerCase(hostName(req.get_header_value("Host")));
    if (name.empty() || isAddress(name) || name == "localhost" || name == lowerCase(listenHost) || isListed(name, allowedHosts))
        return std::nullopt;
    return HttpError(421, "this server does not answer to the name '" + name.substr(0, 100) +
                              "'; address it by its IP address, or ask the operator to add the name with --allow-host");
}

}  // namespace lenslab
