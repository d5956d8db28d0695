#pragma once
// The soft tissue: extended position-based dynamics (XPBD, Macklin et al., MIG 2016) on the simulation mesh's tets
// with the fixed corotated material as a deviatoric and a hydrostatic constraint per tet, solved together, with
// compliances from each region's Young's modulus and Poisson ratio. docs/simulator.md ("Tissue") says why.
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

    /// One step of `dt` s in `substeps` substeps of one solver sweep each: external forces (N per point), the tets,
    /// the tethers, the contacts, damping. Each contact's lambda is then its mean force over the step times dt^2.
    void step(double dt, int substeps, const std::vector<Vec3>& externalForcesN, std::vector<ContactPair>& contacts,
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
    double damping = 40.0;
    /// Mass scaling: the tissue's inertia times this (docs/simulator.md, "Tissue"). What the scope and the fluid do to
    /// the uterus is quasi-static (its elastic waves cross it in about 10 ms); heavier points keep each substep's
    /// motion small against the tets, so two substeps per 5 ms stay stable under the distension load.
    double massScale = 100.0;
    /// Compliance of a contact, m/N: 10 N/mm, far stiffer than the wall under a 2.9 mm tip (about 0.1 N/mm), so the
    /// tissue yields first and the scope never slips through a face below 20 N.
    double contactCompliance = 1e-4;

private:
    void solveTet(std::size_t t, double dt2);
    void solveContacts(std::vector<ContactPair>& contacts, const std::vector<Triangle>& surface, double dt2);
    void solveTethers(double dt2);

    std::vector<Vec3> rest_, x_, prev_, v_;
    std::vector<double> w_; ///< inverse mass, 1/kg (0: fixed)
    std::vector<Tet> tets_;
    std::vector<std::array<double, 9>> dmInv_;    ///< inverse rest shape matrix, row-major
    std::vector<double> volume_;                  ///< m^3
    std::vector<double> mu_, lambda_;             ///< Pa
    std::vector<double> lambdaH_, lambdaD_;       ///< per-step multipliers
    std::vector<std::array<double, 4>> rotation_; ///< per tet, the last rotation found (a unit quaternion w, x, y, z)
    std::vector<std::pair<std::int32_t, double>> tethers_;
    std::vector<double> lambdaT_;
};

} // namespace hs::sim::detail
