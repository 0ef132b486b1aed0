#pragma once
// The Host check against DNS rebinding: a page on attacker.example, whose name the attacker then
// points at 127.0.0.1, reaches a loopback server as "same origin" with Host: attacker.example.
// Only requests naming the server by an IP address, "localhost", the address it listens on or a
// name the operator allows (--allow-host) are answered; others get 421.
#include <httplib.h>

#include <optional>
#include <string>

#include "core/HttpError.h"

namespace lenslab {

// The refusal for a request whose Host the server does not answer to, or nullopt. A request
// without Host (HTTP/1.0; browsers always send one) passes.
std::optional<HttpError> refuseHost(const httplib::Request& req, const std::string& listenHost,
                                    const std::string& allowedHosts);

}  // namespace lenslab
