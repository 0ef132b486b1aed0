#include "film/BayerMosaic.h"

namespace lenslab {

namespace {

constexpr char kChannelLetters[] = "rgb";

}  // namespace

BayerPattern BayerPattern::from(int x0, int y0) const {
    BayerPattern p;
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 2; ++x) p.channels[std::size_t(y * 2 + x)] = channelAt(x0 + x, y0 + y);
    return p;
}

std::string BayerPattern::name() const {
    std::string s;
    for (int c : channels) s += kChannelLetters[c];
    return s;
}

std::optional<BayerPattern> bayerPatternNamed(const std::string& name) {
    for (const char* known : kBayerPatternNames)
        if (name == known) {
            BayerPattern p;
            for (std::size_t i = 0; i < 4; ++i) p.channels[i] = name[i] == 'r' ? 0 : name[i] == 'g' ? 1 : 2;
            return p;
        }
    return std::nullopt;
}

}  // namespace lenslab
