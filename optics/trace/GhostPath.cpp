#include "trace/GhostPath.h"

#include "prescription/OpticsError.h"

namespace lenslab {

std::vector<int> reflectingSurfaces(const LensSystem& lens) {
    std::vector<int> out;
    for (int i = 0; i < int(lens.surfaces.size()); ++i) {
        const Surface& s = lens.surfaces[i];
        if (!s.mirror && !s.isStop && (lens.indexBefore(i) != s.indexAfter || !s.coating.bare())) out.push_back(i);
    }
    return out;
}

std::vector<GhostPath> ghostPaths(const LensSystem& lens) {
    const std::vector<int> surfaces = reflectingSurfaces(lens);
    std::vector<GhostPath> paths;
    for (std::size_t a = 0; a < surfaces.size(); ++a)
        for (std::size_t b = 0; b < a; ++b) paths.push_back({surfaces[a], surfaces[b]});
    return paths;
}

UnfoldedGhost unfoldGhost(const LensSystem& lens, GhostPath path) {
    const int n = int(lens.surfaces.size());
    if (!(0 <= path.second && path.second < path.first && path.first < n))
        throw OpticsError("a ghost reflects at surface i and then at an earlier surface j: 1 <= j < i <= " +
                          std::to_string(n) + ", got i = " + std::to_string(path.first + 1) + ", j = " +
                          std::to_string(path.second + 1));
    const auto mediumBefore = [&](int k) { return k == 0 ? air() : lens.surfaces[k - 1].mediumAfter; };
    const auto indexBefore = [&](int k) { return lens.indexBefore(k); };
    UnfoldedGhost g;
    g.lens = lens;
    g.lens.surfaces.clear();
    g.lens.stopIndex = -1;
    const auto add = [&](int k, bool fromScene, bool reflects, Surface s) {
        if (s.isStop && g.lens.stopIndex < 0) g.lens.stopIndex = int(g.lens.surfaces.size());
        g.lens.surfaces.push_back(std::move(s));
        g.steps.push_back({k, fromScene, reflects || lens.surfaces[k].mirror});
    };
    // A surface turned into a mirror: the light stays in the medium it arrived through.
    const auto asMirror = [&](int k, bool fromScene) {
        Surface s = lens.surfaces[k];
        s.mirror = true;
        s.mediumAfter = fromScene ? mediumBefore(k) : lens.surfaces[k].mediumAfter;
        s.indexAfter = fromScene ? indexBefore(k) : lens.surfaces[k].indexAfter;
        return s;
    };
    for (int k = 0; k < path.first; ++k) add(k, true, false, lens.surfaces[k]);
    add(path.first, true, true, asMirror(path.first, true));
    for (int k = path.first - 1; k > path.second; --k) {
        // Met from the film side, the light leaves into the medium on the scene side (a mirror of
        // the lens's own keeps it where it is: its medium after is the one before).
        Surface s = lens.surfaces[k];
        s.mediumAfter = s.mirror ? s.mediumAfter : mediumBefore(k);
        s.indexAfter = s.mirror ? s.indexAfter : indexBefore(k);
        add(k, false, false, s);
    }
    add(path.second, false, true, asMirror(path.second, false));
    for (int k = path.second + 1; k < n; ++k) add(k, true, false, lens.surfaces[k]);
    return g;
}

}  // namespace lenslab
