#pragma once
// The soft tissue: extended position-based dynamics (XPBD, Macklin et al., MIG 2016) on the simulation mesh's tets
// with the stable Neo-Hookean constraints of Macklin & Muller (2021), a hydrostatic and a deviatoric constraint per
// tet with compliances from each region's Young's modulus and Poisson ratio. docs/simulator.md ("Tissue") says why.
// SI units inside (m, kg, s, Pa, N); the interface speaks mm like the rest of the project.

#include "hs/core/TetMesh.h"
#include "hs/core/Vec3.h"

#include <array>
#include <cstdint>
#include <vector>

namespace hs::sim::detail {

struct TetMaterial {
    double youngsModulusPa = 30e3;
    double poissonRatio = 0.47;
    double densityKgPerM3 = 1050.0;
};

/// A contact of the scope with a surface triangle, found before the iterations and re-solved in each.
struct ContactPair {
    std::int32_t triangle = -1;
    Vec3 centre;         ///< m, the sphere's centre (a point of the shaft)
    double radius = 0.0; ///< m
    double lambda = 0.0; ///< accumulated XPBD multiplier (kg m)
    Vec3 normal;         ///< the triangle's outward normal at the last solve
    bool tip = false;    ///< the sphere at the tip
};

class TissueModel {
public:
    /// `mesh` in mm; one material per tet; `fixed` points never move; `tethers` (point, stiffness N/m) pull a point
    /// back to its rest position (the ligaments and the organs around the uterus).
    void build(const TetMesh& mesh, const std::vector<TetMaterial>& materials, const std::vector<bool>& fixed,
               const std::vector<std::pair<std::int32_t, double>>& tethers);

    /// One step of `dt` s: external forces (N per point), `iterations` solver sweeps with the contacts, damping.
    void step(double dt, int iterations, const std::vector<Vec3>& externalForcesN, std::vector<ContactPair>& contacts,
              const std::vector<Triangle>& surface);

    /// Points in mm (current) and at rest.
    void pointsMm(std::vector<Vec3>& out) const;
    const std::vector<Vec3>& positionsM() const { return x_; }
    const std::vector<Vec3>& restM() const { return rest_; }
    std::size_t pointCount() const { return x_.size(); }
    double inverseMass(std::size_t point) const { return w_[point]; }

    double elasticEnergyJ() const;
    double minVolumeRatio(std::size_t& inverted) const;
    double maxSpeedMPerS() const;

    /// Damping of the velocity, 1/s (a viscous tissue; docs/simulator.md).
    double damping = 20.0;

private:
    void solveTet(std::size_t t, double dt2);
    void solveContacts(std::vector<ContactPair>& contacts, const std::vector<Triangle>& surface);
    void solveTethers(double dt2);

    std::vector<Vec3> rest_, x_, prev_, v_;
    std::vector<double> w_; ///< inverse mass, 1/kg (0: fixed)
    std::vector<Tet> tets_;
    std::vector<std::array<double, 9>> dmInv_; ///< inverse rest shape matrix, row-major
    std::vector<double> volume_;               ///< m^3
    std::vector<double> mu_, lambda_;          ///< Pa
    std::vector<double> lambdaH_, lambdaD_;    ///< per-step multipliers
    std::vector<std::pair<std::int32_t, double>> tethers_;
    std::vector<double> lambdaT_;
};

} // namespace hs::sim::detail
