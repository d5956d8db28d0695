#include "Delaunay.h"

#include "MeshImprove.h"

#include "hs/core/Rng.h"
#include "hs/meshing/Geometry.h"

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_cell_base_with_info_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <unordered_map>
#include <utility>

namespace hs::meshing::detail {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using VertexBase = CGAL::Triangulation_vertex_base_with_info_3<std::uint32_t, Kernel>;
/// Per cell: whether it belongs to the mesh (-1 unknown); reset whenever a vertex of the cell moves.
struct CellState {
    std::int8_t kept = -1;
};
using CellBase =
    CGAL::Triangulation_cell_base_with_info_3<CellState, Kernel, CGAL::Delaunay_triangulation_cell_base_3<Kernel>>;
using Tds = CGAL::Triangulation_data_structure_3<VertexBase, CellBase>;
using Delaunay = CGAL::Delaunay_triangulation_3<Kernel, Tds>;
using VertexHandle = Delaunay::Vertex_handle;
using CellHandle = Delaunay::Cell_handle;
using Point = Kernel::Point_3;

Vec3 toVec(const Point& p) {
    return {p.x(), p.y(), p.z()};
}

class SliverRepair {
public:
    SliverRepair(Delaunay& dt, std::vector<VertexHandle>& handles, std::vector<Vec3>& points,
                 const SliverRepairParams& params, const SliverRepairCallbacks& callbacks)
        : m_dt(dt), m_handles(handles), m_points(points), m_params(params), m_cb(callbacks) {}

    bool kept(CellHandle c) {
        if (c->info().kept < 0) {
            std::array<std::uint32_t, 4> ids{};
            Vec3 centroid;
            for (int k = 0; k < 4; ++k) {
                ids[static_cast<std::size_t>(k)] = c->vertex(k)->info();
                centroid += toVec(c->vertex(k)->point());
            }
            c->info().kept = (m_cb.surelyKept(ids) || m_cb.kept(centroid * 0.25)) ? 1 : 0;
        }
        return c->info().kept == 1;
    }

    /// Smallest dihedral angle of a kept finite cell, or a large value for cells that are infinite or not kept.
    double cellScore(CellHandle c) {
        if (m_dt.is_infinite(c))
            return 1e9;
        const double q = minDihedralDeg(toVec(c->vertex(0)->point()), toVec(c->vertex(1)->point()),
                                        toVec(c->vertex(2)->point()), toVec(c->vertex(3)->point()));
        if (q >= m_params.minDihedralDeg || !kept(c))
            return std::max(q, m_params.minDihedralDeg);
        return q;
    }

    double starScore(VertexHandle v) {
        m_cells.clear();
        m_dt.incident_cells(v, std::back_inserter(m_cells));
        double worst = 1e9;
        for (const CellHandle& c : m_cells)
            worst = std::min(worst, cellScore(c));
        return worst;
    }

    void forgetStar(VertexHandle v) {
        m_cells.clear();
        m_dt.incident_cells(v, std::back_inserter(m_cells));
        for (const CellHandle& c : m_cells)
            c->info().kept = -1;
    }

    /// Tries seeded positions for `v`, scored against the faces of its current link (the star is kept
    /// combinatorially), then moves it in the triangulation and keeps the move only if the Delaunay star improved.
    bool improveVertex(VertexHandle v, int round) {
        const std::uint32_t id = v->info();
        const double before = starScore(v);
        if (before >= m_params.minDihedralDeg)
            return false;
        // Link faces, oriented so that (v, face) is positive, of kept cells only.
        m_link.clear();
        for (const CellHandle& c : m_cells) {
            if (m_dt.is_infinite(c) || !kept(c))
                continue;
            const int i = c->index(v);
            std::array<Vec3, 3> f;
            for (int k = 1; k <= 3; ++k)
                f[static_cast<std::size_t>(k - 1)] = toVec(c->vertex((i + k) & 3)->point());
            // Vertices (i+1, i+2, i+3) with v first give a positive tet when i is even; swap otherwise.
            if (i % 2 == 1)
                std::swap(f[1], f[2]);
            m_link.push_back(f);
        }
        const Vec3 o = toVec(v->point());
        auto linkScore = [&](const Vec3& p) {
            double worst = 1e9;
            for (const auto& f : m_link)
                worst = std::min(worst, minDihedralDeg(p, f[0], f[1], f[2]));
            return worst;
        };
        Rng rng = Rng(m_params.seed).derive((std::uint64_t(id) << 8) ^ std::uint64_t(round));
        double best = linkScore(o);
        Vec3 bestPos = o;
        for (int a = 0; a < m_params.attempts; ++a) {
            const Vec3 dir = normalized(Vec3(rng.normal(), rng.normal(), rng.normal()));
            Vec3 candidate = o + dir * (m_params.step * rng.uniform(0.2, 1.0));
            if (!m_cb.constrain(id, candidate))
                continue;
            const double score = linkScore(candidate);
            if (score > best) {
                best = score;
                bestPos = candidate;
            }
        }
        if (bestPos == o)
            return false;
        const Point origin = v->point();
        forgetStar(v);
        if (m_dt.move_if_no_collision(v, Point(bestPos.x, bestPos.y, bestPos.z)) != v)
            return false;
        forgetStar(v);
        if (starScore(v) <= before) {
            forgetStar(v);
            m_dt.move_if_no_collision(v, origin);
            forgetStar(v);
            return false;
        }
        m_points[id] = bestPos;
        return true;
    }

    void collectBad(CellHandle c, std::vector<std::array<std::uint32_t, 4>>& bad) {
        if (cellScore(c) < m_params.minDihedralDeg) {
            std::array<std::uint32_t, 4> ids{};
            for (int k = 0; k < 4; ++k)
                ids[static_cast<std::size_t>(k)] = c->vertex(k)->info();
            std::sort(ids.begin(), ids.end());
            bad.push_back(ids);
        }
    }

    std::vector<std::array<std::uint32_t, 4>> allBadCells() {
        std::vector<std::array<std::uint32_t, 4>> bad;
        for (auto c = m_dt.finite_cells_begin(); c != m_dt.finite_cells_end(); ++c)
            collectBad(c, bad);
        std::sort(bad.begin(), bad.end());
        return bad;
    }

    /// Bad cells around the given vertices (those moved or tried in the last round).
    std::vector<std::array<std::uint32_t, 4>> badCellsAround(const std::vector<std::uint32_t>& vertices) {
        std::vector<std::array<std::uint32_t, 4>> bad;
        for (std::uint32_t id : vertices) {
            m_cells.clear();
            m_dt.incident_cells(m_handles[id], std::back_inserter(m_cells));
            for (const CellHandle& c : m_cells)
                if (!m_dt.is_infinite(c))
                    collectBad(c, bad);
        }
        std::sort(bad.begin(), bad.end());
        bad.erase(std::unique(bad.begin(), bad.end()), bad.end());
        return bad;
    }

    Status run(Progress& progress, std::size_t& repaired, std::size_t& moved) {
        auto bad = allBadCells();
        const std::size_t initial = bad.size();
        for (int round = 0; round < m_params.rounds && !bad.empty(); ++round) {
            std::vector<std::uint32_t> touched;
            for (const auto& ids : bad) {
                HS_TRY(progress.check("meshing", "removing slivers"));
                CellHandle c;
                int i0, i1, i2, i3;
                if (!m_dt.is_cell(m_handles[ids[0]], m_handles[ids[1]], m_handles[ids[2]], m_handles[ids[3]], c, i0, i1,
                                  i2, i3))
                    continue; // already gone
                if (cellScore(c) >= m_params.minDihedralDeg)
                    continue;
                for (std::uint32_t id : ids) {
                    touched.push_back(id);
                    if (improveVertex(m_handles[id], round)) {
                        ++moved;
                        m_link.clear();
                        std::vector<VertexHandle> ring;
                        m_dt.adjacent_vertices(m_handles[id], std::back_inserter(ring));
                        for (const VertexHandle& w : ring)
                            if (!m_dt.is_infinite(w))
                                touched.push_back(w->info());
                        break;
                    }
                }
            }
            std::sort(touched.begin(), touched.end());
            touched.erase(std::unique(touched.begin(), touched.end()), touched.end());
            bad = badCellsAround(touched);
        }
        const std::size_t left = allBadCells().size();
        repaired = initial > left ? initial - left : 0;
        return {};
    }

private:
    Delaunay& m_dt;
    std::vector<VertexHandle>& m_handles;
    std::vector<Vec3>& m_points;
    const SliverRepairParams& m_params;
    const SliverRepairCallbacks& m_cb;
    std::vector<CellHandle> m_cells;
    std::vector<std::array<Vec3, 3>> m_link;
};

} // namespace

Result<DelaunayOutput> delaunayTetrahedra(std::vector<Vec3>& points, const SliverRepairParams& params,
                                          const SliverRepairCallbacks& callbacks, Progress& progress) {
    if (points.size() < 4)
        return fail(ErrorCode::InvalidInput, "Delaunay tetrahedralization needs at least 4 points");
    try {
        std::vector<std::pair<Point, std::uint32_t>> input;
        input.reserve(points.size());
        for (std::size_t i = 0; i < points.size(); ++i)
            input.emplace_back(Point(points[i].x, points[i].y, points[i].z), static_cast<std::uint32_t>(i));
        Delaunay dt(input.begin(), input.end());
        if (dt.number_of_vertices() != points.size())
            return fail(ErrorCode::Internal, "Delaunay tetrahedralization merged duplicate points");
        HS_TRY(progress.check("meshing"));
        std::vector<VertexHandle> handles(points.size());
        for (auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end(); ++v)
            handles[v->info()] = v;

        DelaunayOutput out;
        if (callbacks.constrain) {
            SliverRepair repair(dt, handles, points, params, callbacks);
            HS_TRY(repair.run(progress, out.repairedTets, out.movedVertices));
        }

        std::unordered_map<Delaunay::Cell*, std::int64_t> index;
        index.reserve(dt.number_of_finite_cells());
        out.tets.reserve(dt.number_of_finite_cells());
        for (auto cell = dt.finite_cells_begin(); cell != dt.finite_cells_end(); ++cell) {
            Tet t;
            for (int k = 0; k < 4; ++k)
                t[static_cast<std::size_t>(k)] = static_cast<std::int32_t>(cell->vertex(k)->info());
            index.emplace(&*cell, static_cast<std::int64_t>(out.tets.size()));
            out.tets.push_back(t); // CGAL cells are positively oriented
        }
        out.neighbours.resize(out.tets.size());
        std::size_t t = 0;
        for (auto cell = dt.finite_cells_begin(); cell != dt.finite_cells_end(); ++cell, ++t)
            for (int k = 0; k < 4; ++k) {
                const CellHandle nb = cell->neighbor(k);
                out.neighbours[t][static_cast<std::size_t>(k)] = dt.is_infinite(nb) ? -1 : index.at(&*nb);
            }
        return out;
    } catch (const std::exception& e) {
        return fail(ErrorCode::BackendFailure, std::string("CGAL Delaunay triangulation failed: ") + e.what());
    }
}

} // namespace hs::meshing::detail
