// TetGen 1.5 baseline (AGPL: this file is built only into the optional hs_meshing_tetgen target).
#define TETLIBRARY
#include <tetgen.h>

#include "../BaselineSupport.h"
#include "hs/meshing/BaselineMeshers.h"

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace hs::meshing {
namespace {

/// Volume of the regular tetrahedron of edge l: the -a bound that gives about the target edge length.
double regularTetVolume(double l) {
    return l * l * l / (6.0 * std::sqrt(2.0));
}

void fillInput(const RegionModel& body, double edge, tetgenio& in) {
    in.firstnumber = 0;
    std::size_t points = 0, facets = 0;
    for (const auto& rs : body.surfaces) {
        points += rs.surface.points.size();
        facets += rs.surface.triangles.size();
    }
    in.numberofpoints = static_cast<int>(points);
    in.pointlist = new REAL[points * 3];
    in.numberoffacets = static_cast<int>(facets);
    in.facetlist = new tetgenio::facet[facets];
    in.facetmarkerlist = new int[facets];
    std::size_t p = 0, f = 0;
    for (std::size_t s = 0; s < body.surfaces.size(); ++s) {
        const SurfaceMesh& mesh = body.surfaces[s].surface;
        const auto offset = static_cast<int>(p);
        for (const Vec3& v : mesh.points) {
            in.pointlist[3 * p] = v.x;
            in.pointlist[3 * p + 1] = v.y;
            in.pointlist[3 * p + 2] = v.z;
            ++p;
        }
        for (const Triangle& t : mesh.triangles) {
            tetgenio::facet& facet = in.facetlist[f];
            tetgenio::init(&facet);
            facet.numberofpolygons = 1;
            facet.polygonlist = new tetgenio::polygon[1];
            tetgenio::init(&facet.polygonlist[0]);
            facet.polygonlist[0].numberofvertices = 3;
            facet.polygonlist[0].vertexlist = new int[3];
            for (int k = 0; k < 3; ++k)
                facet.polygonlist[0].vertexlist[k] = offset + t[static_cast<std::size_t>(k)];
            in.facetmarkerlist[f] = static_cast<int>(s) + 1;
            ++f;
        }
    }
    // One region seed per surface (attribute = index + 1), holes for void regions.
    const std::vector<int> parent = detail::parentSurfaces(body);
    std::vector<Vec3> regionPoints, holePoints;
    std::vector<int> regionAttribute;
    for (std::size_t s = 0; s < body.surfaces.size(); ++s) {
        Vec3 inside;
        if (!detail::interiorPoint(body, s, parent, inside))
            continue;
        if (body.surfaces[s].regionId == RegionModel::kVoidRegion) {
            holePoints.push_back(inside);
        } else {
            regionPoints.push_back(inside);
            regionAttribute.push_back(static_cast<int>(s) + 1);
        }
    }
    in.numberofregions = static_cast<int>(regionPoints.size());
    in.regionlist = new REAL[regionPoints.size() * 5 + 1];
    for (std::size_t r = 0; r < regionPoints.size(); ++r) {
        in.regionlist[5 * r] = regionPoints[r].x;
        in.regionlist[5 * r + 1] = regionPoints[r].y;
        in.regionlist[5 * r + 2] = regionPoints[r].z;
        in.regionlist[5 * r + 3] = regionAttribute[r];
        in.regionlist[5 * r + 4] = regularTetVolume(edge);
    }
    in.numberofholes = static_cast<int>(holePoints.size());
    in.holelist = new REAL[holePoints.size() * 3 + 1];
    for (std::size_t h = 0; h < holePoints.size(); ++h) {
        in.holelist[3 * h] = holePoints[h].x;
        in.holelist[3 * h + 1] = holePoints[h].y;
        in.holelist[3 * h + 2] = holePoints[h].z;
    }
}

} // namespace

Result<MeshResult> meshTetGen(const RegionModel& body, const MeshParams& params, Progress& progress) {
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
    tetgenio in, out;
    {
        ScopedStepTimer timer(result.timings, "tetrahedralize");
        fillInput(body, *edge, in);
        // p: piecewise linear complex; q1.2: radius-edge bound; a: per-region volume bounds; A: region attributes;
        // Q: quiet. TetGen cannot be interrupted: cancellation is checked before and after.
        std::string switches = "pq1.2aAQ";
        try {
            tetrahedralize(switches.data(), &in, &out);
        } catch (int code) {
            return fail(ErrorCode::BackendFailure, "TetGen failed with code " + std::to_string(code));
        } catch (...) {
            return fail(ErrorCode::BackendFailure, "TetGen failed");
        }
    }
    HS_TRY(progress.check("meshing"));
    {
        ScopedStepTimer timer(result.timings, "clean");
        TetMesh& mesh = result.mesh;
        mesh.points.resize(static_cast<std::size_t>(out.numberofpoints));
        for (std::size_t i = 0; i < mesh.points.size(); ++i)
            mesh.points[i] = {out.pointlist[3 * i], out.pointlist[3 * i + 1], out.pointlist[3 * i + 2]};
        const auto nt = static_cast<std::size_t>(out.numberoftetrahedra);
        const auto corners = static_cast<std::size_t>(out.numberofcorners);
        mesh.tets.resize(nt);
        mesh.regions.resize(nt, body.surfaces[0].regionId);
        for (std::size_t t = 0; t < nt; ++t) {
            for (std::size_t k = 0; k < 4; ++k)
                mesh.tets[t][k] = out.tetrahedronlist[t * corners + k];
            if (out.numberoftetrahedronattributes > 0) {
                const auto attr = static_cast<int>(std::lround(
                    out.tetrahedronattributelist[t * static_cast<std::size_t>(out.numberoftetrahedronattributes)]));
                if (attr >= 1 && attr <= static_cast<int>(body.surfaces.size()))
                    mesh.regions[t] = body.surfaces[static_cast<std::size_t>(attr - 1)].regionId;
            }
        }
        detail::orientPositive(mesh);
    }
    {
        ScopedStepTimer timer(result.timings, "quality");
        result.quality = measureQuality(result.mesh, &body, params.threads);
    }
    return result;
}

} // namespace hs::meshing
