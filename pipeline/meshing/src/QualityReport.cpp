#include "hs/meshing/QualityReport.h"

#include "hs/core/Parallel.h"
#include "hs/core/SurfaceMesh.h"
#include "hs/core/TetMesh.h"
#include "hs/core/TriangleGrid.h"
#include "hs/meshing/Geometry.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <memory>

namespace hs::meshing {
namespace {

constexpr std::size_t kChunk = 8192;

struct ShapeSums {
    double radiusRatioSum = 0.0, edgeRatioSum = 0.0;
    double minRadiusRatio = 1.0, minDihedral = 180.0, maxDihedral = 0.0, maxEdgeRatio = 0.0;
    std::array<std::size_t, 10> rrHist{};
    std::array<std::size_t, 9> dihHist{};
    std::size_t slivers = 0, inverted = 0, degenerate = 0;
};

double meanEdgeLength(const TetMesh& mesh) {
    double sum = 0.0;
    std::size_t count = 0;
    const std::size_t step = std::max<std::size_t>(1, mesh.tets.size() / 1000);
    for (std::size_t t = 0; t < mesh.tets.size(); t += step) {
        const Tet& tet = mesh.tets[t];
        for (int i = 0; i < 4; ++i)
            for (int j = i + 1; j < 4; ++j) {
                sum += distance(mesh.points[static_cast<std::size_t>(tet[static_cast<std::size_t>(i)])],
                                mesh.points[static_cast<std::size_t>(tet[static_cast<std::size_t>(j)])]);
                ++count;
            }
    }
    return count ? sum / double(count) : 0.0;
}

void measureShapes(const TetMesh& mesh, int threads, QualityReport& report) {
    const double l = meanEdgeLength(mesh);
    const double degenerateVolume = 1e-12 * l * l * l;
    std::vector<ShapeSums> partial(chunkCount(mesh.tets.size(), kChunk));
    parallelChunks(mesh.tets.size(), kChunk, threads, [&](std::size_t c, std::size_t begin, std::size_t end) {
        ShapeSums& s = partial[c];
        for (std::size_t t = begin; t < end; ++t) {
            const Tet& tet = mesh.tets[t];
            const TetShape shape =
                tetShape(mesh.points[static_cast<std::size_t>(tet[0])], mesh.points[static_cast<std::size_t>(tet[1])],
                         mesh.points[static_cast<std::size_t>(tet[2])], mesh.points[static_cast<std::size_t>(tet[3])]);
            s.radiusRatioSum += shape.radiusRatio;
            s.edgeRatioSum += std::isfinite(shape.edgeRatio) ? shape.edgeRatio : 0.0;
            s.minRadiusRatio = std::min(s.minRadiusRatio, shape.radiusRatio);
            s.minDihedral = std::min(s.minDihedral, shape.minDihedral);
            s.maxDihedral = std::max(s.maxDihedral, shape.maxDihedral);
            s.maxEdgeRatio = std::max(s.maxEdgeRatio, shape.edgeRatio);
            ++s.rrHist[static_cast<std::size_t>(std::clamp(int(shape.radiusRatio * 10.0), 0, 9))];
            ++s.dihHist[static_cast<std::size_t>(std::clamp(int(shape.minDihedral / 10.0), 0, 8))];
            if (shape.minDihedral < kSliverDihedralDeg)
                ++s.slivers;
            if (std::fabs(shape.volume) <= degenerateVolume)
                ++s.degenerate;
            else if (shape.volume < 0.0)
                ++s.inverted;
        }
    });
    ShapeSums total;
    for (const ShapeSums& s : partial) {
        total.radiusRatioSum += s.radiusRatioSum;
        total.edgeRatioSum += s.edgeRatioSum;
        total.minRadiusRatio = std::min(total.minRadiusRatio, s.minRadiusRatio);
        total.minDihedral = std::min(total.minDihedral, s.minDihedral);
        total.maxDihedral = std::max(total.maxDihedral, s.maxDihedral);
        total.maxEdgeRatio = std::max(total.maxEdgeRatio, s.maxEdgeRatio);
        for (std::size_t i = 0; i < total.rrHist.size(); ++i)
            total.rrHist[i] += s.rrHist[i];
        for (std::size_t i = 0; i < total.dihHist.size(); ++i)
            total.dihHist[i] += s.dihHist[i];
        total.slivers += s.slivers;
        total.inverted += s.inverted;
        total.degenerate += s.degenerate;
    }
    const double n = std::max<double>(1.0, double(mesh.tets.size()));
    report.meanRadiusRatio = mesh.tets.empty() ? 0.0 : total.radiusRatioSum / n;
    report.meanEdgeRatio = mesh.tets.empty() ? 0.0 : total.edgeRatioSum / n;
    report.minRadiusRatio = mesh.tets.empty() ? 0.0 : total.minRadiusRatio;
    report.minDihedralDeg = mesh.tets.empty() ? 0.0 : total.minDihedral;
    report.maxDihedralDeg = total.maxDihedral;
    report.maxEdgeRatio = total.maxEdgeRatio;
    report.radiusRatioHistogram = total.rrHist;
    report.minDihedralHistogram = total.dihHist;
    report.sliverCount = total.slivers;
    report.invertedCount = total.inverted;
    report.degenerateCount = total.degenerate;
}

/// Sample points of a surface: its vertices and its face centroids.
std::vector<Vec3> samplePoints(const SurfaceMesh& mesh) {
    std::vector<Vec3> samples = mesh.points;
    samples.reserve(mesh.points.size() + mesh.triangles.size());
    for (const Triangle& t : mesh.triangles)
        samples.push_back((mesh.points[static_cast<std::size_t>(t[0])] + mesh.points[static_cast<std::size_t>(t[1])] +
                           mesh.points[static_cast<std::size_t>(t[2])]) /
                          3.0);
    return samples;
}

/// Largest distance from `samples` to the nearest of `targets`. Exact, but bounded: the grids are searched nearest
/// box first, each only for triangles closer than the best so far, and a sample stops as soon as it is within the
/// largest distance found so far (it cannot raise the maximum). A multi-region body has a small grid per pathology;
/// searched without a bound, a far-away grid was scanned cell by cell for every sample (18 of 21 s of the merged-body
/// test).
double oneSidedDistance(const std::vector<Vec3>& samples, const std::vector<const TriangleGrid*>& targets,
                        int threads) {
    std::vector<double> partial(chunkCount(samples.size(), kChunk), 0.0);
    parallelChunks(samples.size(), kChunk, threads, [&](std::size_t c, std::size_t begin, std::size_t end) {
        double worst = 0.0;
        std::vector<std::pair<double, std::size_t>> order(targets.size());
        for (std::size_t i = begin; i < end; ++i) {
            for (std::size_t g = 0; g < targets.size(); ++g)
                order[g] = {targets[g]->boxDistance2(samples[i]), g};
            std::sort(order.begin(), order.end());
            double best = std::numeric_limits<double>::infinity();
            for (const auto& [box2, g] : order) {
                if (!(box2 < best) || best <= worst)
                    break;
                const SurfaceHit hit = targets[g]->closestWithin(samples[i], best);
                if (hit.triangle >= 0)
                    best = std::min(best, hit.closest.distance2);
            }
            worst = std::max(worst, best);
        }
        partial[c] = worst;
    });
    double worst = 0.0;
    for (double w : partial)
        worst = std::max(worst, w);
    return std::sqrt(worst);
}

void measureFidelity(const TetMesh& mesh, const RegionModel& reference, int threads, QualityReport& report) {
    report.hasReference = true;
    Bounds box;
    for (const auto& rs : reference.surfaces)
        for (const Vec3& p : rs.surface.points)
            box.add(p);
    report.boundingBoxDiagonal = box.diagonal();

    // Hausdorff distance between the mesh's boundary and interfaces and the input surfaces (void surfaces are
    // boundaries too), both ways, sampled at vertices and face centroids.
    const SurfaceMesh boundary = extractBoundary(mesh, true);
    std::vector<std::unique_ptr<TriangleGrid>> inputGrids;
    std::vector<const TriangleGrid*> inputTargets;
    for (const auto& rs : reference.surfaces) {
        if (rs.surface.triangles.empty())
            continue;
        inputGrids.push_back(std::make_unique<TriangleGrid>(rs.surface));
        inputTargets.push_back(inputGrids.back().get());
    }
    double hausdorff = 0.0;
    if (!boundary.triangles.empty() && !inputTargets.empty()) {
        hausdorff = oneSidedDistance(samplePoints(boundary), inputTargets, threads);
        const TriangleGrid boundaryGrid(boundary);
        for (const auto& rs : reference.surfaces)
            hausdorff = std::max(hausdorff, oneSidedDistance(samplePoints(rs.surface), {&boundaryGrid}, threads));
    } else if (!inputTargets.empty()) {
        hausdorff = report.boundingBoxDiagonal;
    }
    report.hausdorffDistance = hausdorff;
    report.hausdorffRelative = report.boundingBoxDiagonal > 0.0 ? hausdorff / report.boundingBoxDiagonal : 0.0;

    // Volumes per region.
    std::map<std::int32_t, RegionVolume> byId;
    for (const RegionVolume& rv : inputRegionVolumes(reference))
        byId[rv.regionId] = rv;
    for (const auto& [id, volume] : regionVolumes(mesh)) {
        byId[id].regionId = id;
        byId[id].meshVolume = volume;
    }
    report.volumeError = 0.0;
    for (auto& [id, rv] : byId) {
        rv.relativeError = rv.inputVolume > 0.0 ? std::fabs(rv.meshVolume - rv.inputVolume) / rv.inputVolume : 1.0;
        report.volumeError = std::max(report.volumeError, rv.relativeError);
        report.regions.push_back(rv);
    }
}

} // namespace

std::vector<RegionVolume> inputRegionVolumes(const RegionModel& model) {
    const std::size_t n = model.surfaces.size();
    std::vector<double> volume(n, 0.0);
    for (std::size_t i = 0; i < n; ++i)
        volume[i] = std::fabs(enclosedVolume(model.surfaces[i].surface));
    // Each surface's region loses the volume of the surfaces directly nested in it (its children).
    std::vector<double> own = volume;
    for (std::size_t j = 1; j < n; ++j) {
        const SurfaceMesh& sj = model.surfaces[j].surface;
        if (sj.triangles.empty())
            continue;
        const Vec3 probe = sj.points[static_cast<std::size_t>(sj.triangles[0][0])];
        for (std::size_t k = j; k-- > 0;) {
            const SurfaceMesh& sk = model.surfaces[k].surface;
            if (std::fabs(windingNumber(sk, probe)) > 0.5) {
                own[k] -= volume[j];
                break;
            }
        }
    }
    std::map<std::int32_t, double> byId;
    for (std::size_t i = 0; i < n; ++i)
        if (model.surfaces[i].regionId != RegionModel::kVoidRegion)
            byId[model.surfaces[i].regionId] += own[i];
    std::vector<RegionVolume> out;
    for (const auto& [id, v] : byId) {
        RegionVolume rv;
        rv.regionId = id;
        rv.inputVolume = v;
        out.push_back(rv);
    }
    return out;
}

QualityReport measureQuality(const TetMesh& mesh, const RegionModel* reference, int threads) {
    QualityReport report;
    report.vertexCount = mesh.points.size();
    report.tetCount = mesh.tets.size();
    threads = resolveThreads(threads);
    measureShapes(mesh, threads, report);
    const SurfaceTopology outer = analyzeTopology(extractBoundary(mesh));
    report.boundaryNonManifoldEdges = outer.nonManifoldEdges;
    report.boundaryNonManifoldVertices = outer.nonManifoldVertices;
    if (reference)
        measureFidelity(mesh, *reference, threads, report);
    return report;
}

std::vector<TetShape> tetShapes(const TetMesh& mesh, int threads) {
    std::vector<TetShape> shapes(mesh.tets.size());
    parallelChunks(mesh.tets.size(), kChunk, threads, [&](std::size_t, std::size_t begin, std::size_t end) {
        for (std::size_t t = begin; t < end; ++t) {
            const Tet& tet = mesh.tets[t];
            shapes[t] =
                tetShape(mesh.points[static_cast<std::size_t>(tet[0])], mesh.points[static_cast<std::size_t>(tet[1])],
                         mesh.points[static_cast<std::size_t>(tet[2])], mesh.points[static_cast<std::size_t>(tet[3])]);
        }
    });
    return shapes;
}

std::vector<std::size_t> worstTets(const std::vector<double>& value, std::size_t count) {
    std::vector<std::size_t> order(value.size());
    for (std::size_t i = 0; i < order.size(); ++i)
        order[i] = i;
    count = std::min(count, order.size());
    const auto less = [&](std::size_t a, std::size_t b) {
        return value[a] < value[b] || (value[a] == value[b] && a < b);
    };
    std::partial_sort(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(count), order.end(), less);
    order.resize(count);
    return order;
}

} // namespace hs::meshing
