// The region of every tet: by its centroid, corrected in thin layers; boundary slivers peeled.
#include "MesherSteps.h"

#include "hs/core/Parallel.h"
#include "hs/meshing/Geometry.h"

#include <algorithm>
#include <cmath>

namespace hs::meshing::detail {

namespace {

/// Boundary tets flatter than this (smallest dihedral, degrees) whose four vertices lie on the boundary are peeled.
constexpr double kPeelDihedralDeg = 15.0;
constexpr std::size_t kTetChunk = 8192;

} // namespace

/// Removes flat tets at the boundary whose four vertices are boundary particles: they are the caps and slivers a
/// Delaunay tetrahedralization leaves on a curved surface; taking them away only flips a surface diagonal.
/// `region` is per Delaunay tet (negative: not in the mesh); peeled tets get kOutside. Only caps on the outline or
/// a void surface (all four vertices on that one surface) exposed to the outside are peeled: in a layer between two
/// nested surfaces thinner than one edge (a 0.8 mm cover over a pathology) every tet has four boundary particles and
/// is flat, and peeling would open the layer and then eat the pathology's own caps behind it.
std::size_t peelBoundarySlivers(const RegionModel& body, const std::vector<Vec3>& points, const detail::Particles& ps,
                                const detail::DelaunayOutput& dt, std::vector<std::int32_t>& region) {
    const std::size_t n = dt.tets.size();
    auto onBoundary = [&](std::int32_t v) {
        return ps.kind[static_cast<std::size_t>(v)] != detail::ParticleKind::Inner;
    };
    auto onePeelableSurface = [&](const Tet& tet) {
        const std::int32_t s = ps.surface[static_cast<std::size_t>(tet[0])];
        for (std::size_t i = 1; i < 4; ++i)
            if (ps.surface[static_cast<std::size_t>(tet[i])] != s)
                return false;
        return s == 0 || body.surfaces[static_cast<std::size_t>(s)].regionId == RegionModel::kVoidRegion;
    };
    auto peelable = [&](std::size_t t) {
        const Tet& tet = dt.tets[t];
        if (region[t] < 0 || !std::all_of(tet.begin(), tet.end(), onBoundary) || !onePeelableSurface(tet))
            return false;
        bool exposed = false;
        for (std::size_t f = 0; f < 4 && !exposed; ++f) {
            const std::int64_t nb = dt.neighbours[t][f];
            exposed = nb < 0 || region[static_cast<std::size_t>(nb)] < 0;
        }
        if (!exposed)
            return false;
        const TetShape s = tetShape(points[static_cast<std::size_t>(tet[0])], points[static_cast<std::size_t>(tet[1])],
                                    points[static_cast<std::size_t>(tet[2])], points[static_cast<std::size_t>(tet[3])]);
        return s.minDihedral < kPeelDihedralDeg;
    };
    std::vector<std::size_t> queue;
    for (std::size_t t = 0; t < n; ++t)
        if (peelable(t))
            queue.push_back(t);
    std::size_t count = 0;
    for (std::size_t head = 0; head < queue.size(); ++head) {
        const std::size_t t = queue[head];
        if (!peelable(t))
            continue;
        region[t] = VoxelSpace::kOutside;
        ++count;
        for (std::size_t f = 0; f < 4; ++f) {
            const std::int64_t nb = dt.neighbours[t][f];
            if (nb >= 0 && peelable(static_cast<std::size_t>(nb)))
                queue.push_back(static_cast<std::size_t>(nb));
        }
    }
    return count;
}

/// The region of every tet by its centroid (negative: outside the body or in a void).
std::vector<std::int32_t> classifyTets(const std::vector<Vec3>& points, const RegionLocator& locator, int threads,
                                       const std::vector<Tet>& tets) {
    std::vector<std::int32_t> region(tets.size());
    parallelChunks(tets.size(), kTetChunk, threads, [&](std::size_t, std::size_t b, std::size_t e) {
        for (std::size_t t = b; t < e; ++t) {
            const Tet& tet = tets[t];
            const Vec3 c = (points[static_cast<std::size_t>(tet[0])] + points[static_cast<std::size_t>(tet[1])] +
                            points[static_cast<std::size_t>(tet[2])] + points[static_cast<std::size_t>(tet[3])]) *
                           0.25;
            region[t] = locator.regionAt(c);
        }
    });
    return region;
}

/// Tets whose four vertices are boundary particles of a surface and of the surface it is directly nested in lie in
/// the layer between the two, i.e. in the outer surface's region. Their centroid says otherwise where the layer is
/// thinner than one edge: between the chords of the outer surface and the caps of the inner one the centroid can
/// fall inside the inner surface, and the tet then joins the pathology although it touches the outline. Tets the
/// centroid puts outside the body stay outside (a Delaunay tet may bridge a crease of the outline).
std::size_t classifyLayerTets(const RegionModel& body, const std::vector<std::int32_t>& parent,
                              const detail::Particles& ps, const std::vector<Tet>& tets,
                              std::vector<std::int32_t>& region) {
    if (body.surfaces.size() < 2)
        return 0;
    std::size_t changed = 0;
    for (std::size_t t = 0; t < tets.size(); ++t) {
        if (region[t] < 0)
            continue;
        std::int32_t lo = std::numeric_limits<std::int32_t>::max(), hi = -1;
        bool boundaryOnly = true;
        for (auto v : tets[t]) {
            const auto i = static_cast<std::size_t>(v);
            boundaryOnly = boundaryOnly && ps.kind[i] != detail::ParticleKind::Inner;
            lo = std::min(lo, ps.surface[i]);
            hi = std::max(hi, ps.surface[i]);
        }
        if (!boundaryOnly || lo == hi || parent[static_cast<std::size_t>(hi)] != lo)
            continue;
        bool twoSurfaces = true;
        for (auto v : tets[t])
            twoSurfaces = twoSurfaces && (ps.surface[static_cast<std::size_t>(v)] == lo ||
                                          ps.surface[static_cast<std::size_t>(v)] == hi);
        const std::int32_t layer = body.surfaces[static_cast<std::size_t>(lo)].regionId;
        if (!twoSurfaces || layer == RegionModel::kVoidRegion || region[t] == layer)
            continue;
        region[t] = layer;
        ++changed;
    }
    return changed;
}

} // namespace hs::meshing::detail
