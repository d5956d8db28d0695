// CGAL Mesh_3 baseline (optional target hs_meshing_cgal): the only file that includes Mesh_3.
#include "../BaselineSupport.h"
#include "hs/meshing/BaselineMeshers.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Mesh_polyhedron_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polyhedral_complex_mesh_domain_3.h>
#include <CGAL/make_mesh_3.h>

#include <cmath>
#include <exception>
#include <map>

namespace hs::meshing {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Polyhedron = CGAL::Mesh_polyhedron_3<Kernel>::type;
using Domain = CGAL::Polyhedral_complex_mesh_domain_3<Kernel, Polyhedron>;
using Tr = CGAL::Mesh_triangulation_3<Domain, CGAL::Default, CGAL::Sequential_tag>::type;
using C3t3 = CGAL::Mesh_complex_3_in_triangulation_3<Tr, Domain::Corner_index, Domain::Curve_index>;
using Criteria = CGAL::Mesh_criteria_3<Tr>;

/// Optimisation budget per optimiser, s (the bench stays bounded; CGAL stops earlier when converged).
constexpr double kOptimiserTimeLimit = 30.0;

Polyhedron toPolyhedron(const SurfaceMesh& mesh) {
    std::vector<Kernel::Point_3> points;
    points.reserve(mesh.points.size());
    for (const Vec3& p : mesh.points)
        points.emplace_back(p.x, p.y, p.z);
    std::vector<std::vector<std::size_t>> polygons;
    polygons.reserve(mesh.triangles.size());
    const bool inward = enclosedVolume(mesh) < 0.0;
    for (const Triangle& t : mesh.triangles) {
        if (inward)
            polygons.push_back({std::size_t(t[0]), std::size_t(t[2]), std::size_t(t[1])});
        else
            polygons.push_back({std::size_t(t[0]), std::size_t(t[1]), std::size_t(t[2])});
    }
    Polyhedron poly;
    CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, polygons, poly);
    return poly;
}

} // namespace

Result<MeshResult> meshCgal(const RegionModel& body, const MeshParams& params, Progress& progress) {
    MeshResult result;
    {
        ScopedStepTimer timer(result.timings, "validate");
        HS_TRY(validate(body));
    }
    auto edge = resolveEdgeLength(body, params);
    if (!edge.ok())
        return edge.failure();
    result.targetEdgeLength = *edge;
    HS_TRY(progress.check("meshing"));
    try {
        ScopedStepTimer timer(result.timings, "tetrahedralize");
        // Subdomain of surface s's inside = s + 1; its outside = its parent's inside (0 outside the body). Void
        // regions become subdomain 0, which Mesh_3 does not mesh.
        const std::vector<int> parent = detail::parentSurfaces(body);
        auto subdomain = [&](int s) {
            if (s < 0 || body.surfaces[static_cast<std::size_t>(s)].regionId == RegionModel::kVoidRegion)
                return 0;
            return s + 1;
        };
        std::vector<Polyhedron> polyhedra;
        std::vector<std::pair<int, int>> incident;
        for (std::size_t s = 0; s < body.surfaces.size(); ++s) {
            polyhedra.push_back(toPolyhedron(body.surfaces[s].surface));
            incident.emplace_back(subdomain(static_cast<int>(s)), subdomain(parent[s]));
        }
        CGAL::Random rng(static_cast<unsigned int>(params.seed & 0x7FFFFFFFu));
        Domain domain(polyhedra.begin(), polyhedra.end(), incident.begin(), incident.end(), &rng);
        domain.detect_features(params.featureAngleDeg > 0.0 ? 180.0 - params.featureAngleDeg : 135.0);
        const double l = *edge;
        Criteria criteria(CGAL::parameters::edge_size = l, CGAL::parameters::facet_angle = 25.0,
                          CGAL::parameters::facet_size = l, CGAL::parameters::facet_distance = 0.05 * l,
                          CGAL::parameters::cell_radius_edge_ratio = 3.0, CGAL::parameters::cell_size = l);
        namespace P = CGAL::parameters;
        C3t3 c3t3 = CGAL::make_mesh_3<C3t3>(domain, criteria, P::odt(P::time_limit = kOptimiserTimeLimit),
                                            P::lloyd(P::time_limit = kOptimiserTimeLimit),
                                            P::perturb(P::time_limit = kOptimiserTimeLimit),
                                            P::exude(P::time_limit = kOptimiserTimeLimit));
        HS_TRY(progress.check("meshing"));
        // Export the cells of the complex.
        std::map<Tr::Vertex_handle, std::int32_t> index;
        TetMesh& mesh = result.mesh;
        for (auto cell = c3t3.cells_in_complex_begin(); cell != c3t3.cells_in_complex_end(); ++cell) {
            Tet t{};
            for (int k = 0; k < 4; ++k) {
                const Tr::Vertex_handle v = cell->vertex(k);
                auto [it, inserted] = index.try_emplace(v, static_cast<std::int32_t>(mesh.points.size()));
                if (inserted) {
                    const auto& p = v->point().point();
                    mesh.points.push_back({CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())});
                }
                t[static_cast<std::size_t>(k)] = it->second;
            }
            mesh.tets.push_back(t);
            const int sub = c3t3.subdomain_index(cell);
            mesh.regions.push_back(sub >= 1 && sub <= static_cast<int>(body.surfaces.size())
                                       ? body.surfaces[static_cast<std::size_t>(sub - 1)].regionId
                                       : body.surfaces[0].regionId);
        }
        detail::orientPositive(mesh);
    } catch (const std::exception& e) {
        return fail(ErrorCode::BackendFailure, std::string("CGAL Mesh_3 failed: ") + e.what());
    }
    {
        ScopedStepTimer timer(result.timings, "quality");
        result.quality = measureQuality(result.mesh, &body, params.threads);
    }
    return result;
}

} // namespace hs::meshing
