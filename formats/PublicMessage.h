#pragma once
// Messages as anyone may read them: what the API answers, a job's error, the public report. The
// one sanitiser every route's message passes through:
// - a path on the server becomes its file name ("/srv/lenslab/data/lenses/upload-1.dat:3" ->
//   "upload-1.dat:3"): where the service keeps its files is nobody's business (the API's own
//   paths, /api/... and /report/..., stay);
// - a value quoted from the input, or any word, is cut at about 40 characters ("…" marks the cut),
//   so an answer never echoes a megabyte it was sent;
// - control characters become spaces.
#include <string>

namespace lenslab {

constexpr std::size_t kShownValueCharacters = 40;

std::string publicMessage(const std::string& message);

}  // namespace lenslab
