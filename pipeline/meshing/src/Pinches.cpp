#include "Pinches.h"

#include <algorithm>
#include <array>
#include <functional>
#include <numeric>
#include <utility>

namespace hs::meshing::detail {
namespace {

using Face = std::array<std::int32_t, 3>;
using Edge = std::pair<std::int32_t, std::int32_t>;

/// Faces of the kept tets with the tets on their sides, sorted by face: bucketed by their smallest vertex with a
/// counting sort (linear), then sorted within each bucket (a few dozen faces).
struct FaceTable {
    std::vector<std::pair<Face, std::int64_t>> entries; ///< (face, tet), sorted
    std::vector<std::size_t> bucket;                    ///< entries of smallest vertex v: [bucket[v], bucket[v + 1])
    explicit FaceTable(const std::vector<Tet>& tets, const std::vector<std::int32_t>& region) {
        std::int32_t vertices = 0;
        for (std::size_t t = 0; t < tets.size(); ++t)
            if (region[t] >= 0)
                for (std::int32_t v : tets[t])
                    vertices = std::max(vertices, v + 1);
        bucket.assign(static_cast<std::size_t>(vertices) + 1, 0);
        auto forEachFace = [&](auto&& visit) {
            for (std::size_t t = 0; t < tets.size(); ++t) {
                if (region[t] < 0)
                    continue;
                const Tet& k = tets[t];
                const auto id = static_cast<std::int64_t>(t);
                visit(sortedFace(k[1], k[2], k[3]), id);
                visit(sortedFace(k[0], k[2], k[3]), id);
                visit(sortedFace(k[0], k[1], k[3]), id);
                visit(sortedFace(k[0], k[1], k[2]), id);
            }
        };
        forEachFace([&](const Face& f, std::int64_t) { ++bucket[static_cast<std::size_t>(f[0]) + 1]; });
        std::partial_sum(bucket.begin(), bucket.end(), bucket.begin());
        entries.resize(bucket.back());
        std::vector<std::size_t> fill(bucket.begin(), bucket.end() - 1);
        forEachFace([&](const Face& f, std::int64_t t) { entries[fill[static_cast<std::size_t>(f[0])]++] = {f, t}; });
        for (std::size_t v = 0; v + 1 < bucket.size(); ++v)
            std::sort(entries.begin() + static_cast<std::ptrdiff_t>(bucket[v]),
                      entries.begin() + static_cast<std::ptrdiff_t>(bucket[v + 1]));
    }
    /// The tet across `face` from tet `t`, -1 when the face is on the boundary.
    std::int64_t across(const Face& face, std::int64_t t) const {
        const auto v = static_cast<std::size_t>(face[0]);
        if (v + 1 >= bucket.size())
            return -1;
        for (std::size_t i = bucket[v]; i < bucket[v + 1]; ++i)
            if (entries[i].first == face && entries[i].second != t)
                return entries[i].second;
        return -1;
    }
};

std::vector<Edge> pinchedEdges(const FaceTable& faces) {
    std::vector<Edge> edges;
    const auto& e = faces.entries;
    for (std::size_t i = 0; i < e.size();) {
        std::size_t j = i + 1;
        while (j < e.size() && e[j].first == e[i].first)
            ++j;
        if (j - i == 1) { // a boundary face
            const Face& f = e[i].first;
            edges.emplace_back(f[0], f[1]);
            edges.emplace_back(f[0], f[2]);
            edges.emplace_back(f[1], f[2]);
        }
        i = j;
    }
    std::sort(edges.begin(), edges.end());
    std::vector<Edge> pinched;
    for (std::size_t i = 0; i < edges.size();) {
        std::size_t j = i + 1;
        while (j < edges.size() && edges[j] == edges[i])
            ++j;
        if (j - i > 2)
            pinched.push_back(edges[i]);
        i = j;
    }
    return pinched;
}

std::int64_t findRoot(std::vector<std::int64_t>& parent, std::int64_t x) {
    while (parent[static_cast<std::size_t>(x)] != x) {
        parent[static_cast<std::size_t>(x)] = parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(x)])];
        x = parent[static_cast<std::size_t>(x)];
    }
    return x;
}

/// The fans of tets around a simplex (an edge or a vertex): the tets of `ring` (all containing the simplex) joined
/// across shared faces (which then contain the simplex too).
std::vector<std::vector<std::int64_t>> fansOf(const std::vector<Tet>& tets, const std::vector<std::int64_t>& ring) {
    std::vector<std::int64_t> parent(ring.size());
    std::iota(parent.begin(), parent.end(), 0);
    for (std::size_t i = 0; i < ring.size(); ++i)
        for (std::size_t j = i + 1; j < ring.size(); ++j) {
            const Tet& u = tets[static_cast<std::size_t>(ring[i])];
            const Tet& w = tets[static_cast<std::size_t>(ring[j])];
            int shared = 0;
            for (std::int32_t x : u)
                shared += std::find(w.begin(), w.end(), x) != w.end() ? 1 : 0;
            if (shared == 3)
                parent[static_cast<std::size_t>(findRoot(parent, static_cast<std::int64_t>(i)))] =
                    findRoot(parent, static_cast<std::int64_t>(j));
        }
    std::vector<std::vector<std::int64_t>> fans;
    std::vector<std::int64_t> rootOf;
    for (std::size_t i = 0; i < ring.size(); ++i) {
        const std::int64_t r = findRoot(parent, static_cast<std::int64_t>(i));
        const auto it = std::find(rootOf.begin(), rootOf.end(), r);
        const auto k = static_cast<std::size_t>(it - rootOf.begin());
        if (it == rootOf.end()) {
            rootOf.push_back(r);
            fans.emplace_back();
        }
        fans[k].push_back(ring[i]);
    }
    return fans;
}

/// A pinch: an edge (a < b), a vertex whose tets form several fans (b = kSeveralFans), or a vertex whose tets form one
/// fan but whose boundary faces form several pieces (b = kSeveralSheets): the fan wraps round a void that passes
/// through the vertex, so the boundary is two sheets touching at a point there.
using Pinch = std::pair<std::int32_t, std::int32_t>;
constexpr std::int32_t kSeveralFans = -1;
constexpr std::int32_t kSeveralSheets = -2;

/// The pieces of the boundary round vertex `v`: the boundary faces of `ring`'s tets that contain `v` (a tet and the
/// face's index in it), grouped by the edges through `v` they share. Empty when `v` is inside.
std::vector<std::vector<std::pair<std::int64_t, int>>> sheetsAround(const std::vector<Tet>& tets,
                                                                    const std::vector<std::int32_t>& region,
                                                                    const FaceTable& faces, std::int32_t v,
                                                                    const std::vector<std::int64_t>& ring) {
    std::vector<std::pair<std::int64_t, int>> onBoundary;
    std::vector<Face> faceOf;
    for (std::int64_t t : ring) {
        const Tet& k = tets[static_cast<std::size_t>(t)];
        for (int f = 0; f < 4; ++f) {
            if (k[static_cast<std::size_t>(f)] == v)
                continue; // the face opposite v does not contain it
            const Face face =
                sortedFace(k[static_cast<std::size_t>((f + 1) & 3)], k[static_cast<std::size_t>((f + 2) & 3)],
                           k[static_cast<std::size_t>((f + 3) & 3)]);
            const std::int64_t nb = faces.across(face, t);
            if (nb < 0 || region[static_cast<std::size_t>(nb)] < 0) { // removed tets leave boundary
                onBoundary.emplace_back(t, f);
                faceOf.push_back(face);
            }
        }
    }
    std::vector<std::int64_t> parent(onBoundary.size());
    std::iota(parent.begin(), parent.end(), 0);
    for (std::size_t i = 0; i < faceOf.size(); ++i)
        for (std::size_t j = i + 1; j < faceOf.size(); ++j) {
            int shared = 0;
            for (std::int32_t x : faceOf[i])
                shared += std::find(faceOf[j].begin(), faceOf[j].end(), x) != faceOf[j].end() ? 1 : 0;
            if (shared >= 2) // an edge through v (both faces contain v)
                parent[static_cast<std::size_t>(findRoot(parent, static_cast<std::int64_t>(i)))] =
                    findRoot(parent, static_cast<std::int64_t>(j));
        }
    std::vector<std::vector<std::pair<std::int64_t, int>>> sheets;
    std::vector<std::int64_t> rootOf;
    for (std::size_t i = 0; i < onBoundary.size(); ++i) {
        const std::int64_t r = findRoot(parent, static_cast<std::int64_t>(i));
        const auto it = std::find(rootOf.begin(), rootOf.end(), r);
        if (it == rootOf.end()) {
            rootOf.push_back(r);
            sheets.emplace_back();
        }
        sheets[static_cast<std::size_t>(std::find(rootOf.begin(), rootOf.end(), r) - rootOf.begin())].push_back(
            onBoundary[i]);
    }
    return sheets;
}

/// Pinched edges and vertices of the kept tets: boundary edges with more than two boundary faces, and boundary
/// vertices whose tets form more than one fan. `rings` gets the tets around each.
std::vector<Pinch> findPinches(const std::vector<Tet>& tets, const std::vector<std::int32_t>& region,
                               const FaceTable& faces, std::vector<std::vector<std::int64_t>>& rings) {
    // Vertex -> tets (CSR by a counting sort; tets ascending per vertex).
    std::vector<std::size_t> first(faces.bucket.size(), 0);
    for (std::size_t t = 0; t < tets.size(); ++t)
        if (region[t] >= 0)
            for (std::int32_t v : tets[t])
                ++first[static_cast<std::size_t>(v) + 1];
    std::partial_sum(first.begin(), first.end(), first.begin());
    std::vector<std::int64_t> incident(first.back());
    {
        std::vector<std::size_t> fill(first.begin(), first.end() - 1);
        for (std::size_t t = 0; t < tets.size(); ++t)
            if (region[t] >= 0)
                for (std::int32_t v : tets[t])
                    incident[fill[static_cast<std::size_t>(v)]++] = static_cast<std::int64_t>(t);
    }
    auto tetsAround = [&](std::int32_t a, std::int32_t b) {
        std::vector<std::int64_t> ring;
        const auto va = static_cast<std::size_t>(a);
        for (std::size_t i = first[va]; i < first[va + 1]; ++i) {
            const Tet& k = tets[static_cast<std::size_t>(incident[i])];
            if (b < 0 || std::find(k.begin(), k.end(), b) != k.end())
                ring.push_back(incident[i]);
        }
        return ring;
    };
    std::vector<Pinch> pinches;
    rings.clear();
    for (const Edge& e : pinchedEdges(faces)) {
        pinches.push_back(e);
        rings.push_back(tetsAround(e.first, e.second));
    }
    std::vector<std::int32_t> boundaryVertices;
    const auto& entries = faces.entries;
    for (std::size_t i = 0; i < entries.size();) {
        std::size_t j = i + 1;
        while (j < entries.size() && entries[j].first == entries[i].first)
            ++j;
        if (j - i == 1)
            boundaryVertices.insert(boundaryVertices.end(), entries[i].first.begin(), entries[i].first.end());
        i = j;
    }
    std::sort(boundaryVertices.begin(), boundaryVertices.end());
    boundaryVertices.erase(std::unique(boundaryVertices.begin(), boundaryVertices.end()), boundaryVertices.end());
    for (std::int32_t v : boundaryVertices) {
        std::vector<std::int64_t> ring = tetsAround(v, -1);
        if (fansOf(tets, ring).size() > 1) {
            pinches.emplace_back(v, kSeveralFans);
            rings.push_back(std::move(ring));
        } else if (sheetsAround(tets, region, faces, v, ring).size() > 1) {
            pinches.emplace_back(v, kSeveralSheets);
            rings.push_back(std::move(ring));
        }
    }
    return pinches;
}

/// The tets of `ring` (all around one vertex, one fan) whose removal joins the vertex's boundary sheets into one: a
/// path of tets joined across faces from a tet on the first sheet to a tet on another, every tet `removable`, the
/// cheapest by `cost` (per tet, > 0). Cutting the fan (an annulus round the vertex, seen from it) across from one of
/// its rims to the other leaves a disc: one sheet. Empty when one sheet is left or no such path exists. Dijkstra over
/// the ring, ties to the lower position in it: deterministic.
template <class Removable, class Cost>
std::vector<std::int64_t>
bridgeBetweenSheets(const std::vector<Tet>& tets, const std::vector<std::vector<std::pair<std::int64_t, int>>>& sheets,
                    const std::vector<std::int64_t>& ring, Removable&& removable, Cost&& cost) {
    if (sheets.size() < 2)
        return {};
    const std::size_t n = ring.size();
    auto onSheet = [&](std::int64_t t, bool first) {
        for (std::size_t s = first ? 0 : 1; s < (first ? 1 : sheets.size()); ++s)
            for (const auto& face : sheets[s])
                if (face.first == t)
                    return true;
        return false;
    };
    auto joined = [&](std::size_t i, std::size_t j) {
        const Tet& u = tets[static_cast<std::size_t>(ring[i])];
        const Tet& w = tets[static_cast<std::size_t>(ring[j])];
        int shared = 0;
        for (std::int32_t x : u)
            shared += std::find(w.begin(), w.end(), x) != w.end() ? 1 : 0;
        return shared == 3;
    };
    constexpr double kUnreached = 1e300;
    std::vector<double> dist(n, kUnreached);
    std::vector<std::int64_t> from(n, -1);
    std::vector<char> done(n, 0);
    for (std::size_t i = 0; i < n; ++i)
        if (removable(ring[i]) && onSheet(ring[i], true))
            dist[i] = cost(ring[i]);
    for (;;) {
        std::size_t i = n;
        for (std::size_t k = 0; k < n; ++k)
            if (!done[k] && dist[k] < kUnreached && (i == n || dist[k] < dist[i]))
                i = k;
        if (i == n)
            return {};
        done[i] = 1;
        if (onSheet(ring[i], false)) {
            std::vector<std::int64_t> path;
            for (std::int64_t k = static_cast<std::int64_t>(i); k >= 0; k = from[static_cast<std::size_t>(k)])
                path.push_back(ring[static_cast<std::size_t>(k)]);
            return path;
        }
        for (std::size_t j = 0; j < n; ++j)
            if (!done[j] && joined(i, j) && removable(ring[j]) && dist[i] + cost(ring[j]) < dist[j]) {
                dist[j] = dist[i] + cost(ring[j]);
                from[j] = static_cast<std::int64_t>(i);
            }
    }
}

} // namespace

PinchStats openPinches(std::vector<Tet>& tets, std::vector<std::int32_t>& region, std::int32_t outerRegion,
                       const std::function<std::int32_t(std::int32_t)>& duplicateVertex) {
    PinchStats stats;
    std::vector<std::vector<std::int64_t>> rings;
    for (int pass = 0; pass < 8; ++pass) {
        const FaceTable faces(tets, region);
        const std::vector<Pinch> pinches = findPinches(tets, region, faces, rings);
        if (pass == 0)
            stats.pinchedBefore = pinches.size();
        if (pinches.empty())
            return stats;                                     // none (left): pinchedAfter stays 0
        std::vector<char> onBoundary(faces.bucket.size(), 0); // vertices with a boundary face
        for (std::size_t i = 0; i < faces.entries.size();) {
            std::size_t j = i + 1;
            while (j < faces.entries.size() && faces.entries[j].first == faces.entries[i].first)
                ++j;
            if (j - i == 1)
                for (std::int32_t v : faces.entries[i].first)
                    onBoundary[static_cast<std::size_t>(v)] = 1;
            i = j;
        }
        // Removing a fan whose vertices all lie on the boundary takes a cap or a spike and leaves no notch; a fan with
        // a vertex inside the body leaves a notch as deep as that vertex lies.
        const auto exposedInner = [&](const std::vector<std::int64_t>& fan) {
            std::size_t inner = 0;
            for (std::int64_t t : fan)
                for (std::int32_t v : tets[static_cast<std::size_t>(t)])
                    inner += onBoundary[static_cast<std::size_t>(v)] ? 0 : 1;
            return inner;
        };
        const auto removableTet = [&](std::int64_t t) {
            if (region[static_cast<std::size_t>(t)] != outerRegion)
                return false;
            const Tet& k = tets[static_cast<std::size_t>(t)];
            for (int f = 0; f < 4; ++f) {
                const Face face =
                    sortedFace(k[static_cast<std::size_t>((f + 1) & 3)], k[static_cast<std::size_t>((f + 2) & 3)],
                               k[static_cast<std::size_t>((f + 3) & 3)]);
                const std::int64_t nb = faces.across(face, t);
                if (nb >= 0 && region[static_cast<std::size_t>(nb)] >= 0 &&
                    region[static_cast<std::size_t>(nb)] != outerRegion)
                    return false;
            }
            return true;
        };
        // A vertex whose tets form several fans, none of which can go without a notch, is split first: a copy of the
        // vertex for each fan but the first. Nothing is removed, and the cones that touched there touch as separate
        // sheets. The face table is stale after a split, so the other pinches wait for the next pass.
        if (duplicateVertex) {
            bool split = false;
            for (std::size_t p = 0; p < pinches.size(); ++p) {
                if (pinches[p].second != kSeveralFans)
                    continue;
                const std::int32_t v = pinches[p].first;
                std::vector<std::int64_t> ring;
                for (std::int64_t t : rings[p]) {
                    const Tet& k = tets[static_cast<std::size_t>(t)];
                    if (region[static_cast<std::size_t>(t)] >= 0 && std::find(k.begin(), k.end(), v) != k.end())
                        ring.push_back(t);
                }
                const auto fans = fansOf(tets, ring);
                const bool shallow = std::any_of(fans.begin(), fans.end(), [&](const std::vector<std::int64_t>& fan) {
                    return exposedInner(fan) == 0 && std::all_of(fan.begin(), fan.end(), removableTet);
                });
                if (shallow)
                    continue; // a cap or a spike: removed below
                for (std::size_t f = 1; f < fans.size(); ++f) {
                    const std::int32_t copy = duplicateVertex(v);
                    // The copy is a boundary vertex as v is. The face table is this pass's, so without this a later
                    // pinch whose fans reach the copy would read past onBoundary's end, and whether a fan counts as
                    // shallow would depend on what the heap held there (a scene differed between two runs).
                    const auto c = static_cast<std::size_t>(copy);
                    if (c >= onBoundary.size())
                        onBoundary.resize(c + 1, 0);
                    onBoundary[c] = onBoundary[static_cast<std::size_t>(v)];
                    for (std::int64_t t : fans[f])
                        for (std::int32_t& x : tets[static_cast<std::size_t>(t)])
                            x = x == v ? copy : x;
                    ++stats.splitVertices;
                    split = true;
                }
            }
            if (split)
                continue;
        }
        bool removedAny = false;
        for (std::size_t p = 0; p < pinches.size(); ++p) {
            std::vector<std::int64_t>& ring = rings[p];
            ring.erase(std::remove_if(ring.begin(), ring.end(),
                                      [&](std::int64_t t) { return region[static_cast<std::size_t>(t)] < 0; }),
                       ring.end());
            if (pinches[p].second == kSeveralSheets) {
                // A tet with a vertex inside the body exposes it: the notch reaches as deep. Such tets cost as much
                // as ten on the boundary, so the bridge keeps to the surface where it can.
                const auto exposes = [&](std::int64_t t) {
                    double c = 1.0;
                    for (std::int32_t v : tets[static_cast<std::size_t>(t)])
                        c += onBoundary[static_cast<std::size_t>(v)] ? 0.0 : 10.0;
                    return c;
                };
                const std::vector<std::int64_t> bridge = bridgeBetweenSheets(
                    tets, sheetsAround(tets, region, faces, pinches[p].first, ring), ring, removableTet, exposes);
                for (std::int64_t t : bridge)
                    region[static_cast<std::size_t>(t)] = -1;
                stats.removedTets += bridge.size();
                removedAny = removedAny || !bridge.empty();
                continue;
            }
            const auto fans = fansOf(tets, ring);
            if (fans.size() < 2)
                continue; // already opened by an earlier removal in this pass
            auto removable = [&](const std::vector<std::int64_t>& fan) {
                return std::all_of(fan.begin(), fan.end(), removableTet);
            };
            const std::vector<std::int64_t>* smallest = nullptr;
            for (const auto& fan : fans)
                if (removable(fan) && (smallest == nullptr || fan.size() < smallest->size()))
                    smallest = &fan;
            if (smallest == nullptr)
                continue;
            for (std::int64_t t : *smallest)
                region[static_cast<std::size_t>(t)] = -1;
            stats.removedTets += smallest->size();
            removedAny = true;
        }
        if (!removedAny)
            break;
    }
    stats.pinchedAfter = findPinches(tets, region, FaceTable(tets, region), rings).size();
    return stats;
}

} // namespace hs::meshing::detail
