// The cellular automaton growth model (Eden-type growth with surface tension).
#include "Shapes.h"

#include "ShapeFields.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace hs::pathology::detail {

namespace {

/// Morphological closing (dilation, then erosion) with a ball of `radius` voxels. An Eden-type automaton leaves
/// one- and two-voxel crevices between its lobes; polygonized, they become creases whose two sides nearly touch, so
/// that smoothing can push them through each other and any offset of the surface folds. Closing fills exactly those
/// crevices and keeps the lobes (Serra, "Image Analysis and Mathematical Morphology", 1982).
std::vector<std::uint8_t> closeOccupancy(const std::vector<std::uint8_t>& occ, const Grid& g, int radius) {
    std::vector<std::array<int, 3>> ball;
    for (int dk = -radius; dk <= radius; ++dk)
        for (int dj = -radius; dj <= radius; ++dj)
            for (int di = -radius; di <= radius; ++di)
                if (di * di + dj * dj + dk * dk <= radius * radius)
                    ball.push_back({di, dj, dk});
    const auto inside = [&](int i, int j, int k) {
        return i >= 0 && j >= 0 && k >= 0 && i < g.nx && j < g.ny && k < g.nz;
    };
    std::vector<std::uint8_t> dilated(occ.size(), 0);
    for (int k = 0; k < g.nz; ++k)
        for (int j = 0; j < g.ny; ++j)
            for (int i = 0; i < g.nx; ++i) {
                if (!occ[g.index(i, j, k)])
                    continue;
                for (const auto& d : ball)
                    if (inside(i + d[0], j + d[1], k + d[2]))
                        dilated[g.index(i + d[0], j + d[1], k + d[2])] = 1;
            }
    std::vector<std::uint8_t> closed(occ.size(), 0);
    for (int k = 0; k < g.nz; ++k)
        for (int j = 0; j < g.ny; ++j)
            for (int i = 0; i < g.nx; ++i) {
                if (!dilated[g.index(i, j, k)])
                    continue;
                bool all = true;
                for (const auto& d : ball)
                    if (!inside(i + d[0], j + d[1], k + d[2]) || !dilated[g.index(i + d[0], j + d[1], k + d[2])]) {
                        all = false;
                        break;
                    }
                closed[g.index(i, j, k)] = all || occ[g.index(i, j, k)] ? 1 : 0;
            }
    return closed;
}

/// Trilinear resampling of `field` (on `g`, zero outside) onto a grid of spacing `h` over the same box.
std::vector<float> resample(const std::vector<float>& field, const Grid& g, double h, Grid& out) {
    Bounds box;
    box.add(g.origin);
    box.add(g.center(g.nx - 1, g.ny - 1, g.nz - 1));
    out = Grid::covering(box, h, 1);
    const auto at = [&](int i, int j, int k) {
        return i < 0 || j < 0 || k < 0 || i >= g.nx || j >= g.ny || k >= g.nz ? 0.0 : double(field[g.index(i, j, k)]);
    };
    std::vector<float> result(out.size());
    for (int k = 0; k < out.nz; ++k)
        for (int j = 0; j < out.ny; ++j)
            for (int i = 0; i < out.nx; ++i) {
                const Vec3 q = (out.center(i, j, k) - g.origin) / g.h;
                const int i0 = static_cast<int>(std::floor(q.x)), j0 = static_cast<int>(std::floor(q.y)),
                          k0 = static_cast<int>(std::floor(q.z));
                const double fx = q.x - i0, fy = q.y - j0, fz = q.z - k0;
                double v = 0.0;
                for (int c = 0; c < 8; ++c) {
                    const int di = c & 1, dj = (c >> 1) & 1, dk = (c >> 2) & 1;
                    const double w = (di ? fx : 1.0 - fx) * (dj ? fy : 1.0 - fy) * (dk ? fz : 1.0 - fz);
                    v += w * at(i0 + di, j0 + dj, k0 + dk);
                }
                result[out.index(i, j, k)] = static_cast<float>(v);
            }
    return result;
}

/// The automaton's surface: closed occupancy (no crevices), blurred at the automaton's resolution, polygonized on a
/// grid of `spacing` mm (coarser than the automaton's voxels: the blurred field has no detail below two voxels, and
/// the organ adaptation and the merge cost grow with the triangle count), then smoothed (Taubin) and evened out.
SurfaceMesh automatonSurface(const std::vector<std::uint8_t>& occ, const Grid& g, const ShapeSpec& spec,
                             double spacing) {
    const std::vector<std::uint8_t> closed = closeOccupancy(occ, g, 2);
    std::vector<float> field(closed.begin(), closed.end());
    if (spec.pedunculated || spec.polyp)
        addCapsule(field, g, spec.base, spec.center, spec.stalkRadius);
    Grid coarse;
    const std::vector<float> sampled = resample(blur(blur(field, g), g), g, spacing, coarse);
    SurfaceMesh mesh = polygonize(sampled, coarse, 0.5f);
    taubinSmooth(mesh, 10);
    relaxTangentially(mesh, 10);
    taubinSmooth(mesh, 10);
    relaxTangentially(mesh, 5);
    orientOutward(mesh);
    return mesh;
}

/// Sweeps between two frames shown to a viewer.
constexpr int kFrameSweeps = 4;

/// The centres of the occupied cells within [lo - 1, hi + 1].
std::vector<Vec3> cellCentres(const std::vector<std::uint8_t>& occ, const Grid& g, const std::array<int, 3>& lo,
                              const std::array<int, 3>& hi) {
    std::vector<Vec3> centres;
    for (int k = std::max(0, lo[2] - 1); k <= std::min(g.nz - 1, hi[2] + 1); ++k)
        for (int j = std::max(0, lo[1] - 1); j <= std::min(g.ny - 1, hi[1] + 1); ++j)
            for (int i = std::max(0, lo[0] - 1); i <= std::min(g.nx - 1, hi[0] + 1); ++i)
                if (occ[g.index(i, j, k)])
                    centres.push_back(g.center(i, j, k));
    return centres;
}

} // namespace

Result<SurfaceMesh> cellularAutomatonShape(const ShapeSpec& spec, const SurfaceMesh& organ, const GrowthTuning& tuning,
                                           Rng& rng, Progress& progress) {
    const double h = 2.0 * spec.radius / tuning.cellsPerDiameter;
    const Grid g = growthGrid(spec, h, 1.6 * spec.radius);
    const std::vector<std::uint8_t> tissue = insideMask(organ, g);
    std::vector<std::uint8_t> occ(g.size(), 0);
    const int ci = static_cast<int>(std::lround((spec.center.x - g.origin.x) / h));
    const int cj = static_cast<int>(std::lround((spec.center.y - g.origin.y) / h));
    const int ck = static_cast<int>(std::lround((spec.center.z - g.origin.z) / h));
    const std::array<std::array<int, 3>, 6> nb{{{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}}};
    occ[g.index(ci, cj, ck)] = 1;
    std::size_t count = 1;
    for (const auto& d : nb) {
        occ[g.index(ci + d[0], cj + d[1], ck + d[2])] = 1;
        ++count;
    }
    const double target = 4.0 / 3.0 * kPi * std::pow(spec.radius, 3) / (h * h * h);
    std::vector<std::size_t> born;
    // Bounding box of the tumour: only its neighbourhood is scanned each sweep.
    std::array<int, 3> lo{ci - 1, cj - 1, ck - 1}, hi{ci + 1, cj + 1, ck + 1};
    for (int sweep = 0; static_cast<double>(count) < target; ++sweep) {
        HS_TRY(progress.check("pathology growth"));
        if (sweep > 4 * tuning.cellsPerDiameter * 10)
            break;
        born.clear();
        for (int k = std::max(1, lo[2] - 1); k <= std::min(g.nz - 2, hi[2] + 1); ++k)
            for (int j = std::max(1, lo[1] - 1); j <= std::min(g.ny - 2, hi[1] + 1); ++j)
                for (int i = std::max(1, lo[0] - 1); i <= std::min(g.nx - 2, hi[0] + 1); ++i) {
                    const std::size_t id = g.index(i, j, k);
                    if (occ[id])
                        continue;
                    int q = 0;
                    Vec3 from;
                    for (const auto& d : nb)
                        if (occ[g.index(i + d[0], j + d[1], k + d[2])]) {
                            ++q;
                            from += Vec3{static_cast<double>(-d[0]), static_cast<double>(-d[1]),
                                         static_cast<double>(-d[2])};
                        }
                    if (q == 0)
                        continue;
                    const double r = tissue[id] ? tuning.tissueResistance : tuning.yieldResistance;
                    // The wall's fibres guide growth along its tangent plane; the cavity and the outside have none.
                    // A transmural (hybrid) myoma, which must reach both the endometrium and the serosa, grows
                    // across the wall instead.
                    const double along = dot(normalized(from), spec.intoWall);
                    const double guide = !tissue[id]       ? 0.0
                                         : spec.transmural ? tuning.transmuralAnisotropy * along * along
                                                           : tuning.anisotropy * (1.0 - along * along);
                    const double p = std::min(1.0, 0.12 * (1.0 + 2.0 * q / 6.0) / r * (1.0 + guide));
                    if (rng.uniform() < p) {
                        born.push_back(id);
                        lo = {std::min(lo[0], i), std::min(lo[1], j), std::min(lo[2], k)};
                        hi = {std::max(hi[0], i), std::max(hi[1], j), std::max(hi[2], k)};
                    }
                }
        for (std::size_t id : born)
            occ[id] = 1;
        count += born.size();
        // Every few sweeps (and the last one) a viewer sees the cells so far.
        if (tuning.observe && (sweep % kFrameSweeps == 0 || static_cast<double>(count) >= target))
            emitFrame(tuning, clinical::GrowthModel::CellularAutomaton, sweep, static_cast<double>(count) >= target,
                      cellCentres(occ, g, lo, hi));
    }
    SurfaceMesh mesh = automatonSurface(occ, g, spec, spec.radius / tuning.surfaceCellsPerRadius);
    // The placement owns the position, the automaton the shape: a tumour that drifted into yielding tissue keeps
    // its lopsided shape but is centred (volume centroid) where it was planned, as the other models are.
    if (!spec.pedunculated && !spec.polyp)
        translate(mesh, spec.center - volumeCentroid(mesh));
    return mesh;
}

} // namespace hs::pathology::detail
