// The particle growth model: dividing cells held together by a confinement.
#include "Shapes.h"

#include "ShapeFields.h"

#include "hs/core/PointGrid.h"

#include <algorithm>
#include <cmath>

namespace hs::pathology::detail {

namespace {

Vec3 randomUnit(Rng& rng) {
    for (;;) {
        const Vec3 v{rng.normal(), rng.normal(), rng.normal()};
        if (norm(v) > 1e-6)
            return normalized(v);
    }
}

} // namespace

Result<SurfaceMesh> particleShape(const ShapeSpec& spec, const SurfaceMesh& organ, const GrowthTuning& tuning, Rng& rng,
                                  Progress& progress) {
    const double h = 2.0 * spec.radius / tuning.cellsPerDiameter;
    const Grid g = growthGrid(spec, h, 1.6 * spec.radius);
    const std::vector<std::uint8_t> tissue = insideMask(organ, g);
    auto inTissue = [&](const Vec3& p) {
        const int i = static_cast<int>(std::lround((p.x - g.origin.x) / h));
        const int j = static_cast<int>(std::lround((p.y - g.origin.y) / h));
        const int k = static_cast<int>(std::lround((p.z - g.origin.z) / h));
        if (i < 0 || j < 0 || k < 0 || i >= g.nx || j >= g.ny || k >= g.nz)
            return false;
        return tissue[g.index(i, j, k)] != 0;
    };
    const auto n = static_cast<std::size_t>(tuning.particleCount);
    const double volume = 4.0 / 3.0 * kPi * std::pow(spec.radius, 3);
    // Cell radius so that n cells in a random close packing (~0.64) fill the volume.
    const double rho = std::cbrt(0.64 * volume * 3.0 / (4.0 * kPi * static_cast<double>(n)));
    std::vector<Vec3> cells{spec.center};
    std::vector<Vec3> disp;
    PointGrid neighbours;
    const double cell = 2.0 * rho; // the repulsion's reach: neighbours lie in the cells around
    for (int generation = 0; cells.size() < n; ++generation) {
        HS_TRY(progress.check("pathology growth"));
        // Division: faster where the surroundings yield (cavity, outside) than in the resisting wall.
        const std::size_t current = cells.size();
        for (std::size_t i = 0; i < current && cells.size() < n; ++i) {
            const double p = inTissue(cells[i]) ? 0.5 / tuning.tissueResistance : 0.5 / tuning.yieldResistance;
            if (rng.uniform() >= std::min(p, 1.0))
                continue;
            const Vec3 d = randomUnit(rng) * (0.5 * rho);
            cells.push_back(cells[i] + d);
            cells[i] -= d;
        }
        // Relaxation: short-range repulsion, confinement strong in the wall, weak where it yields.
        for (int it = 0; it < 8; ++it) {
            Bounds box;
            for (const Vec3& c : cells)
                box.add(c);
            neighbours.reset(box, cell);
            neighbours.insertAll(cells);
            disp.assign(cells.size(), Vec3{});
            for (std::size_t i = 0; i < cells.size(); ++i) {
                neighbours.forEachInCellsAround(cells[i], [&](std::int32_t id) {
                    const auto j = static_cast<std::size_t>(id);
                    if (j <= i)
                        return;
                    Vec3 d = cells[i] - cells[j];
                    double len = norm(d);
                    if (len >= 2.0 * rho)
                        return;
                    if (len < 1e-9) {
                        d = Vec3{1.0, 0.0, 0.0};
                        len = 1.0;
                    }
                    const Vec3 push = d * (0.25 * (2.0 * rho - norm(cells[i] - cells[j])) / len);
                    disp[i] += push;
                    disp[j] -= push;
                });
                const bool wall = inTissue(cells[i]);
                disp[i] -=
                    (cells[i] - spec.center) * (wall ? 0.02 * tuning.tissueResistance : 0.02 * tuning.yieldResistance);
                // The wall's fibres guide growth along its tangent plane; a transmural (hybrid) myoma, which spans
                // the wall, grows across it instead.
                const Vec3 across = spec.intoWall * dot(disp[i], spec.intoWall);
                if (wall)
                    disp[i] -= (spec.transmural ? disp[i] - across : across) * tuning.anisotropy;
            }
            for (std::size_t i = 0; i < cells.size(); ++i)
                cells[i] += disp[i];
        }
        emitFrame(tuning, clinical::GrowthModel::Particles, generation, cells.size() >= n, cells);
    }
    std::vector<float> field(g.size(), 0.0f);
    const double reach = 1.45 * rho;
    const int rv = static_cast<int>(std::ceil(reach / h));
    for (const Vec3& c : cells) {
        const int i0 = static_cast<int>(std::lround((c.x - g.origin.x) / h));
        const int j0 = static_cast<int>(std::lround((c.y - g.origin.y) / h));
        const int k0 = static_cast<int>(std::lround((c.z - g.origin.z) / h));
        for (int k = std::max(1, k0 - rv); k <= std::min(g.nz - 2, k0 + rv); ++k)
            for (int j = std::max(1, j0 - rv); j <= std::min(g.ny - 2, j0 + rv); ++j)
                for (int i = std::max(1, i0 - rv); i <= std::min(g.nx - 2, i0 + rv); ++i)
                    if (norm2(g.center(i, j, k) - c) <= reach * reach)
                        field[g.index(i, j, k)] = 1.0f;
    }
    if (spec.pedunculated || spec.polyp)
        addCapsule(field, g, spec.base, spec.center, spec.stalkRadius);
    return surfaceFromOccupancy(std::move(field), g);
}

} // namespace hs::pathology::detail
