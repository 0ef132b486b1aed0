#pragma once
// Whether the bytes received on a connection hold a whole request, so that HeadWaiter hands it to
// a worker only then: a client sending its head or its body slowly holds no worker thread. A body
// whose length is unknown ahead (chunked) is whole at its last chunk; a client that waits for
// "100 Continue" before sending its body is handed on with its head.
#include <cstddef>
#include <string>

namespace lenslab {

enum class Received { Partial, HeadOnly, Whole };

// HeadOnly: the head is complete and its body still on its way. A declared body larger than
// `maxBodyBytes`, or more bytes than that received, counts as Whole (the worker refuses it at once).
Received receivedOf(const std::string& bytes, std::size_t maxBodyBytes);

}  // namespace lenslab
