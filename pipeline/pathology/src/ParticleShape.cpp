// The particle growth model: dividing cells held together by a confinement.
#include "Shapes.h"

#include "ShapeFields.h"

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
    std::unordered_map<std::int64_t, std::vector<std::size_t>> hash;
    const double cell = 2.0 * rho;
    auto key = [&](const Vec3& p, int dx, int dy, int dz) {
        const auto x = static_cast<std::int64_t>(std::floor(p.x / cell)) + dx;
        const auto y = static_cast<std::int64_t>(std::floor(p.y / cell)) + dy;
        const auto z = static_cast<std::int64_t>(std::floor(p.z / cell)) + dz;
        return (x * 73856093) ^ (y * 19349663) ^ (z * 83492791);
    };
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
            hash.clear();
            for (std::size_t i = 0; i < cells.size(); ++i)
                hash[key(cells[i], 0, 0, 0)].push_back(i);
            disp.assign(cells.size(), Vec3{});
            for (std::size_t i = 0; i < cells.size(); ++i) {
                for (int dz = -1; dz <= 1; ++dz)
                    for (int dy = -1; dy <= 1; ++dy)
                        for (int dx = -1; dx <= 1; ++dx) {
                            auto found = hash.find(key(cells[i], dx, dy, dz));
                            if (found == hash.end())
                                continue;
                            for (std::size_t j : found->second) {
                                if (j <= i)
                                    continue;
                                Vec3 d = cells[i] - cells[j];
                                double len = norm(d);
                                if (len >= 2.0 * rho)
                                    continue;
                                if (len < 1e-9) {
                                    d = Vec3{1.0, 0.0, 0.0};
                                    len = 1.0;
                                }
                                const Vec3 push = d * (0.25 * (2.0 * rho - norm(cells[i] - cells[j])) / len);
                                disp[i] += push;
                                disp[j] -= push;
                            }
                        }
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
