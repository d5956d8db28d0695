#pragma once
/// The steps of the particle mesher (meshParticles) after the particles are placed: tets classified by region,
/// interfaces recovered, kept tets improved.

#include "Delaunay.h"
#include "MeshImprove.h"
#include "Particles.h"
#include "hs/core/Progress.h"
#include "hs/core/RegionModel.h"
#include "hs/core/Timings.h"
#include "hs/core/TriangleGrid.h"
#include "hs/meshing/VoxelSpace.h"

#include <memory>
#include <vector>

namespace hs::meshing::detail {

/// Tets with a smaller dihedral angle (degrees) are improved after extraction: above the bar of 15 with margin.
constexpr double kImproveDihedralDeg = 17.0;
/// Radius-ratio smoothing after the worst-angle improvement: one sweep over the vertices of the tets below 0.7. More
/// sweeps or a higher threshold gain less than 0.003 in the mean at 50k vertices and cost 0.2-0.4 s each.
constexpr int kRadiusRatioSweeps = 1;
constexpr double kRadiusRatioBelow = 0.7;

/// The region of a point: the id of the innermost surface containing it (kOutside outside the body or in a void).
class RegionLocator {
public:
    RegionLocator(const RegionModel& body, const VoxelSpace& voxels) : m_body(body), m_voxels(voxels) {
        for (const auto& rs : body.surfaces)
            m_grids.push_back(std::make_unique<TriangleGrid>(rs.surface, voxels.region.spacing()));
    }
    std::int32_t regionAt(const Vec3& p) const {
        const auto& grid = m_voxels.region;
        const Index3 v = grid.voxelOf(p);
        if (!grid.contains(v))
            return VoxelSpace::kOutside;
        const std::int32_t r = grid.at(v);
        if (r != VoxelSpace::kSurface)
            return r;
        const std::size_t lin = grid.linear(v);
        std::int32_t region = VoxelSpace::kOutside;
        for (std::size_t s = 0; s < m_body.surfaces.size(); ++s) {
            const VoxelLabel l = m_voxels.surfaces[s].labels[lin];
            const bool inside = l == VoxelLabel::Inner || (l == VoxelLabel::Surface && m_grids[s]->inside(p));
            if (inside)
                region = m_body.surfaces[s].regionId == RegionModel::kVoidRegion ? VoxelSpace::kOutside
                                                                                 : m_body.surfaces[s].regionId;
        }
        return region;
    }

    const TriangleGrid& surfaceGrid(std::size_t s) const { return *m_grids[s]; }

private:
    const RegionModel& m_body;
    const VoxelSpace& m_voxels;
    std::vector<std::unique_ptr<TriangleGrid>> m_grids;
};

// TetRegions.cpp
/// Removes flat tets at the boundary whose four vertices are boundary particles: they are the caps and slivers a
/// Delaunay tetrahedralization leaves on a curved surface; taking them away only flips a surface diagonal.
/// `region` is per Delaunay tet (negative: not in the mesh); peeled tets get kOutside. Only caps on the outline or
/// a void surface (all four vertices on that one surface) exposed to the outside are peeled: in a layer between two
/// nested surfaces thinner than one edge (a 0.8 mm cover over a pathology) every tet has four boundary particles and
/// is flat, and peeling would open the layer and then eat the pathology's own caps behind it.
std::size_t peelBoundarySlivers(const RegionModel& body, const std::vector<Vec3>& points, const detail::Particles& ps,
                                const detail::DelaunayOutput& dt, std::vector<std::int32_t>& region);

/// The region of every tet by its centroid (negative: outside the body or in a void).
std::vector<std::int32_t> classifyTets(const std::vector<Vec3>& points, const RegionLocator& locator, int threads,
                                       const std::vector<Tet>& tets);

/// Tets whose four vertices are boundary particles of a surface and of the surface it is directly nested in lie in
/// the layer between the two, i.e. in the outer surface's region. Their centroid says otherwise where the layer is
/// thinner than one edge: between the chords of the outer surface and the caps of the inner one the centroid can
/// fall inside the inner surface, and the tet then joins the pathology although it touches the outline. Tets the
/// centroid puts outside the body stay outside (a Delaunay tet may bridge a crease of the outline).
std::size_t classifyLayerTets(const RegionModel& body, const std::vector<std::int32_t>& parent,
                              const detail::Particles& ps, const std::vector<Tet>& tets,
                              std::vector<std::int32_t>& region);

// InterfaceParticles.cpp
/// Particles hashed by voxel, for "is a particle already this close" tests while particles are added.
class ParticleHash {
public:
    ParticleHash(const VoxelGrid<std::int32_t>& grid, const Particles& ps);
    /// Hashes particle i (added to `ps` after construction).
    void insert(std::size_t i);
    /// Whether a hashed particle lies closer to p than sqrt(radius2) (at most one voxel).
    bool occupied(const Vec3& p, double radius2) const;

private:
    const VoxelGrid<std::int32_t>& m_grid;
    const Particles& m_ps;
    std::vector<std::int32_t> m_head, m_next;
};

/// Tets whose inner particles lie in different regions, or that join an inner particle to a surface that does not
/// bound its region, cross an interface (Delaunay did not recover it there):
/// adds an interface particle where the segment between two such particles meets the nearest nested surface, unless
/// a particle is already close. Returns how many were added; the caller tetrahedralizes again.
std::size_t addInterfaceParticles(const detail::DelaunayOutput& dt, const RegionModel& body,
                                  const RegionLocator& locator, const VoxelSpace& voxels, double edge,
                                  detail::Particles& ps);

// SurfaceFidelity.cpp
/// The tets the mesher keeps of a triangulation, with their regions, by the steps that follow it (centroid, layer,
/// peeling); the points are the particles'.
TetMesh keptTets(const detail::DelaunayOutput& dt, const RegionModel& body, const RegionLocator& locator, int threads,
                 const detail::Particles& ps);

/// Surface particles added where the boundary and interfaces of `kept` (tets on the particles' indices) stray from the
/// input surfaces by more than `tolerance` (mm), both ways, as Delaunay refinement does for a surface's approximation
/// (the facet distance criterion of Boissonnat & Oudot, Graph Models 67:405-451, 2005; CGAL Mesh_3's
/// facet_distance): at each input sample (vertex, face centroid) farther than that from the boundary, and at the
/// input's closest point to each boundary vertex or face centroid farther than that from the input, farthest first,
/// unless a particle of `ps` already lies within `minSpacing`. An inner particle left on the boundary farther than
/// `tolerance` from the input (a notch's floor) is removed from `ps`. Returns how many were added and removed; the
/// caller tetrahedralizes again when that is not 0.
std::size_t addFidelityParticles(const TetMesh& kept, const RegionModel& body, const RegionLocator& locator,
                                 const VoxelSpace& voxels, double tolerance, double minSpacing, int threads,
                                 detail::Particles& ps);

// ConstrainedImprovement.cpp
/// Improves the kept tets (flips, boundary flips, smoothing; see MeshImprove.h) with every particle on its
/// constraint. Replaces `tets` and `region` by the kept, improved tets.
Result<detail::MeshImproveStats> improveTets(const RegionModel& body,
                                             const std::vector<detail::SurfaceAdjacency>& adjacency,
                                             detail::Particles& ps, std::vector<Tet>& tets,
                                             std::vector<std::int32_t>& region, Progress& progress);

void recordImprovement(const detail::MeshImproveStats& stats, StepTiming& step);

// ParticleMesher.cpp
/// The same tet by an even permutation (orientation kept): smallest index first, then the smallest of the rest.
Tet canonicalTet(const Tet& t);

} // namespace hs::meshing::detail
