#include "MasterSignalNote.h"

#include <unistd.h>

#include <cstring>

namespace lenslab {

namespace {

constexpr int kSignals[3] = {SIGTERM, SIGINT, SIGHUP};
volatile std::sig_atomic_t gTilesDone = 0, gTilesTotal = 0;

// Async-signal-safe: only write(2) and a hand-rolled integer format.
void append(char*& p, const char* text) {
    const std::size_t n = std::strlen(text);
    std::memcpy(p, text, n);
    p += n;
}

void appendInt(char*& p, long value) {
    char digits[24];
    int n = 0;
    do {
        digits[n++] = char('0' + value % 10);
        value /= 10;
    } while (value > 0 && n < 20);
    while (n > 0) *p++ = digits[--n];
}

void onSignal(int sig) {
    char text[256];
    char* p = text;
    append(p, "lenslab: MPI render stopped by signal ");
    appendInt(p, sig);
    append(p, " after ");
    appendInt(p, gTilesDone);
    append(p, " of ");
    appendInt(p, gTilesTotal);
    append(p, " tiles (mpirun stops every rank when one dies); no image was written\n");
    [[maybe_unused]] const ssize_t written = ::write(STDERR_FILENO, text, std::size_t(p - text));
    std::signal(sig, SIG_DFL);
    std::raise(sig);
}

}  // namespace

MasterSignalNote::MasterSignalNote(int tilesTotal) {
    gTilesDone = 0;
    gTilesTotal = tilesTotal;
    struct sigaction action = {};
    action.sa_handler = onSignal;
    sigemptyset(&action.sa_mask);
    for (int i = 0; i < 3; ++i) sigaction(kSignals[i], &action, &previous_[i]);
}

MasterSignalNote::~MasterSignalNote() {
    for (int i = 0; i < 3; ++i) sigaction(kSignals[i], &previous_[i], nullptr);
}

void MasterSignalNote::setTilesDone(int tilesDone) { gTilesDone = tilesDone; }

}  // namespace lenslab
