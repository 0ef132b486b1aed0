#include "guards/HostCheck.h"

#include <arpa/inet.h>


#include "core/CommaList.h"
#include "core/LowerCase.h"

namespace lenslab {

namespace {

// "name:port", "[v6]:port" or either without a port -> the name or address alone; a fully
// qualified name's final dot ("localhost.") dropped, as DNS does.
std::string hostName(const std::string& host) {
    if (!host.empty() && host.front() == '[') return host.substr(1, host.find(']') - 1);
    std::string name = host.substr(0, host.find(':'));
    if (name.size() > 1 && name.back() == '.') name.pop_back();
    return name;
}

// An address needs no name lookup, so it cannot be rebound.
bool isAddress(const std::string& name) {
    unsigned char address[16];
    return inet_pton(AF_INET, name.c_str(), address) == 1 || inet_pton(AF_INET6, name.c_str(), address) == 1;
}

bool isListed(const std::string& name, const std::string& list) {
    for (const std::string& entry : commaListEntries(list))
        if (hostName(lowerCase(entry)) == name) return true;  // "a, b." lists b
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
