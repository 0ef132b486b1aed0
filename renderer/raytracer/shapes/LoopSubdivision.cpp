#include "shapes/LoopSubdivision.h"

#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <unordered_map>

namespace lenslab {

namespace {

struct P3 {
    double x = 0, y = 0, z = 0;
};
P3 operator+(P3 a, P3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
P3 operator-(P3 a, P3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
P3 operator*(double s, P3 a) { return {s * a.x, s * a.y, s * a.z}; }

using Tri = std::array<std::uint32_t, 3>;

std::uint64_t edgeKey(std::uint32_t a, std::uint32_t b) {
    return a < b ? (std::uint64_t(a) << 32) | b : (std::uint64_t(b) << 32) | a;
}

// The triangles on each side of an undirected edge.
struct EdgeFaces {
    std::uint32_t face[2] = {0, 0};
    std::uint32_t from = 0;  // the first face walks the edge from this vertex
    int count = 0;
};

// The mesh's adjacency: every edge's faces, and every vertex's one-ring in pbrt-v3's order (interior:
// around the fan from one face across the edge to the next vertex; boundary: from the neighbour on
// the trailing boundary edge back to the one on the leading boundary edge, so that the two boundary
// neighbours come first and last).
struct Adjacency {
    std::unordered_map<std::uint64_t, EdgeFaces> edges;
    std::vector<std::uint32_t> ringStart, ring;
    std::vector<char> boundary;

    std::size_t valence(std::uint32_t v) const { return ringStart[v + 1] - ringStart[v]; }
    const std::uint32_t* ringOf(std::uint32_t v) const { return &ring[ringStart[v]]; }
};

Adjacency adjacency(std::size_t vertexCount, const std::vector<Tri>& faces) {
    Adjacency a;
    a.edges.reserve(faces.size() * 2);
    for (std::uint32_t f = 0; f < faces.size(); ++f)
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t v0 = faces[f][k], v1 = faces[f][(k + 1) % 3];
            EdgeFaces& e = a.edges[edgeKey(v0, v1)];
            if (e.count == 2 || (e.count == 1 && e.from == v0))
                throw std::invalid_argument("the edge between vertices " + std::to_string(v0) + " and " + std::to_string(v1) +
                                            " is shared by more than two triangles or two of the same winding");
            if (e.count == 0) e.from = v0;
            e.face[e.count++] = f;
        }

    // Each face at vertex v is a wedge from its next vertex to its previous one.
    std::vector<std::uint32_t> wedgeStart(vertexCount + 1, 0);
    for (const Tri& t : faces)
        for (std::uint32_t v : t) ++wedgeStart[v + 1];
    for (std::size_t v = 0; v < vertexCount; ++v) wedgeStart[v + 1] += wedgeStart[v];
    std::vector<std::uint32_t> fill(wedgeStart.begin(), wedgeStart.end() - 1), wedgeNext(3 * faces.size()),
        wedgePrev(3 * faces.size());
    for (const Tri& t : faces)
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t slot = fill[t[k]]++;
            wedgeNext[slot] = t[(k + 1) % 3];
            wedgePrev[slot] = t[(k + 2) % 3];
        }

    a.ringStart.assign(vertexCount + 1, 0);
    a.boundary.assign(vertexCount, 0);
    std::vector<std::uint32_t> chain;
    for (std::uint32_t v = 0; v < vertexCount; ++v) {
        const std::uint32_t begin = wedgeStart[v], end = wedgeStart[v + 1];
        auto following = [&](std::uint32_t w) -> std::int64_t {  // the wedge across the edge (v, next of w)
            for (std::uint32_t x = begin; x < end; ++x)
                if (wedgePrev[x] == wedgeNext[w]) return x;
            return -1;
        };
        auto preceding = [&](std::uint32_t w) -> std::int64_t {
            for (std::uint32_t x = begin; x < end; ++x)
                if (wedgeNext[x] == wedgePrev[w]) return x;
            return -1;
        };
        chain.clear();
        if (begin < end) {
            std::uint32_t first = begin;
            for (std::size_t guard = 0; guard < end - begin; ++guard) {  // back to the fan's start, if it has one
                const std::int64_t p = preceding(first);
                if (p < 0) {
                    a.boundary[v] = 1;
                    break;
                }
                first = std::uint32_t(p);
            }
            for (std::int64_t w = first; w >= 0 && chain.size() <= end - begin; w = following(std::uint32_t(w))) {
                if (!chain.empty() && std::uint32_t(w) == first) break;
                chain.push_back(std::uint32_t(w));
            }
            if (chain.size() != end - begin)
                throw std::invalid_argument("the triangles around vertex " + std::to_string(v) + " form more than one fan");
        }
        if (a.boundary[v]) {
            for (auto it = chain.rbegin(); it != chain.rend(); ++it) a.ring.push_back(wedgeNext[*it]);
            a.ring.push_back(wedgePrev[chain.front()]);
        } else {
            for (std::uint32_t w : chain) a.ring.push_back(wedgeNext[w]);
        }
        a.ringStart[v + 1] = std::uint32_t(a.ring.size());
    }
    return a;
}

double beta(std::size_t valence) { return valence == 3 ? 3.0 / 16 : 3.0 / (8.0 * double(valence)); }

P3 ringSum(const std::vector<P3>& p, const Adjacency& a, std::uint32_t v) {
    P3 s;
    for (std::size_t i = 0; i < a.valence(v); ++i) s = s + p[a.ringOf(v)[i]];
    return s;
}

// (1 - n w) p + w (sum of the ring) inside; (1 - 2 w) p + w (both boundary neighbours) on the boundary.
P3 weighted(const std::vector<P3>& p, const Adjacency& a, std::uint32_t v, double interiorWeight, double boundaryWeight) {
    const std::size_t n = a.valence(v);
    if (n == 0) return p[v];
    if (a.boundary[v])
        return (1 - 2 * boundaryWeight) * p[v] + boundaryWeight * (p[a.ringOf(v)[0]] + p[a.ringOf(v)[n - 1]]);
    return (1 - double(n) * interiorWeight) * p[v] + interiorWeight * ringSum(p, a, v);
}

std::uint32_t third(const Tri& t, std::uint32_t a, std::uint32_t b) {
    for (std::uint32_t v : t)
        if (v != a && v != b) return v;
    return t[0];
}

void refine(std::vector<P3>& p, std::vector<Tri>& faces) {
    const Adjacency a = adjacency(p.size(), faces);
    std::vector<P3> next(p.size());
    for (std::uint32_t v = 0; v < p.size(); ++v) next[v] = weighted(p, a, v, beta(a.valence(v)), 1.0 / 8);
    std::unordered_map<std::uint64_t, std::uint32_t> edgeVertex;
    edgeVertex.reserve(a.edges.size());
    std::vector<Tri> children;
    children.reserve(4 * faces.size());
    for (const Tri& t : faces) {
        std::uint32_t mid[3];
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t v0 = t[k], v1 = t[(k + 1) % 3];
            const auto [it, isNew] = edgeVertex.emplace(edgeKey(v0, v1), std::uint32_t(next.size()));
            mid[k] = it->second;
            if (!isNew) continue;
            const EdgeFaces& e = a.edges.at(edgeKey(v0, v1));
            if (e.count == 1) {
                next.push_back(0.5 * (p[v0] + p[v1]));
            } else {
                const P3 far = p[third(faces[e.face[0]], v0, v1)] + p[third(faces[e.face[1]], v0, v1)];
                next.push_back(3.0 / 8 * (p[v0] + p[v1]) + 1.0 / 8 * far);
            }
        }
        children.push_back({t[0], mid[0], mid[2]});
        children.push_back({mid[0], t[1], mid[1]});
        children.push_back({mid[2], mid[1], t[2]});
        children.push_back({mid[0], mid[1], mid[2]});
    }
    p = std::move(next);
    faces = std::move(children);
}

// The limit surface's tangents from the limit positions of the ring (pbrt-v3's stencils); the normal
// is their cross product.
P3 limitNormal(const std::vector<P3>& p, const Adjacency& a, std::uint32_t v) {
    const std::size_t n = a.valence(v);
    const std::uint32_t* r = a.ringOf(v);
    P3 s, t;
    if (n == 0) return {0, 0, 1};
    if (!a.boundary[v]) {
        for (std::size_t j = 0; j < n; ++j) {
            s = s + std::cos(2 * M_PI * double(j) / double(n)) * p[r[j]];
            t = t + std::sin(2 * M_PI * double(j) / double(n)) * p[r[j]];
        }
    } else {
        s = p[r[n - 1]] - p[r[0]];
        if (n == 2) {
            t = p[r[0]] + p[r[1]] - 2 * p[v];
        } else if (n == 3) {
            t = p[r[1]] - p[v];
        } else if (n == 4) {
            t = -1.0 * p[r[0]] + 2.0 * p[r[1]] + 2.0 * p[r[2]] - p[r[3]] - 2.0 * p[v];
        } else {
            const double theta = M_PI / double(n - 1);
            t = std::sin(theta) * (p[r[0]] + p[r[n - 1]]);
            for (std::size_t k = 1; k + 1 < n; ++k) t = t + (2 * std::cos(theta) - 2) * std::sin(double(k) * theta) * p[r[k]];
            t = -1.0 * t;
        }
    }
    return {s.y * t.z - s.z * t.y, s.z * t.x - s.x * t.z, s.x * t.y - s.y * t.x};
}

}  // namespace

MeshData loopSubdivide(const std::vector<Vec3f>& points, const std::vector<std::uint32_t>& indices, int levels) {
    std::vector<P3> p;
    p.reserve(points.size());
    for (const Vec3f& x : points) p.push_back({x.x, x.y, x.z});
    std::vector<Tri> faces;
    for (std::size_t i = 0; i + 2 < indices.size(); i += 3) faces.push_back({indices[i], indices[i + 1], indices[i + 2]});
    for (int level = 0; level < levels; ++level) refine(p, faces);

    const Adjacency a = adjacency(p.size(), faces);
    std::vector<P3> limit(p.size());
    for (std::uint32_t v = 0; v < p.size(); ++v) {
        const double b = beta(a.valence(v));
        const double gamma = a.valence(v) ? 1.0 / (double(a.valence(v)) + 3.0 / (8.0 * b)) : 0.0;
        limit[v] = weighted(p, a, v, gamma, 1.0 / 5);
    }
    MeshData mesh;
    for (std::uint32_t v = 0; v < p.size(); ++v) {
        const P3 n = limitNormal(limit, a, v);
        mesh.p.push_back({float(limit[v].x), float(limit[v].y), float(limit[v].z)});
        mesh.n.push_back({float(n.x), float(n.y), float(n.z)});
    }
    for (const Tri& t : faces) mesh.indices.insert(mesh.indices.end(), t.begin(), t.end());
    return mesh;
}

}  // namespace lenslab
