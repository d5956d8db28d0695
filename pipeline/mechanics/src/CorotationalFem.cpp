#include "hs/mechanics/CorotationalFem.h"

#include "hs/core/Parallel.h"
#include "hs/mechanics/TetMath.h"

#include <Eigen/Eigenvalues>
#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <string>
#include <thread>

#if defined(__linux__)
#include <pthread.h>
#include <sched.h>
#endif
#include <type_traits>

namespace hs::mechanics {

/// The iteration's matrix factored as L D L^T in a two-part nested-dissection order (George 1973): the points cut by
/// a plane into two halves that share no entry of the matrix, each half in its own fill-reducing (AMD) order, and the
/// separator (the first half's points next to the second's) last. L's columns of one half then touch only that half's
/// rows and the separator's, so the two halves' triangular solves run on two threads; the separator's rows gather each
/// half's updates in its own buffer, summed in a fixed order, so the result is the same bits on one thread or two.
struct CorotationalFem::Factor {
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower, Eigen::NaturalOrdering<int>> ldlt;
    std::vector<int> oldToNew; ///< per dof, its place in the factor's order
    std::array<std::size_t, 2>
        partEnd{}; ///< the halves are [0, partEnd[0]) and [partEnd[0], partEnd[1]); the separator follows
    std::vector<int> colStart, row; ///< L's strictly lower part, by column
    std::vector<double> value, diag;
    /// The elimination tree: per column of L its first row below the diagonal (-1: a root). The rows of a column
    /// are its ancestors, so L^-1 b for a b of a few entries is non-zero only on their paths to the root (Gilbert &
    /// Peierls 1988): a forward solve on that reach, not on every column.
    std::vector<int> parent;
    mutable std::vector<double> work, buffer[2];

    /// L^-1 b on its reach: the columns, ascending, and the values.
    struct Sparse {
        std::vector<int> index;
        std::vector<double> value;
    };
    /// L^-1 b for b given by (dof in the factor's order, value) entries (repeats add), with scratch `s` (0 or 1: one
    /// a thread).
    void forward(const std::vector<std::pair<int, double>>& b, std::size_t s, Sparse& out) const;
    /// Scratch `s` sized to the factor, its marks' next stamp.
    std::uint32_t nextStamp(std::size_t s) const;
    /// Scratch of `forward`, one a thread: a zeroed dense vector and the reach's marks.
    mutable std::array<std::vector<double>, 2> dense;
    mutable std::array<std::vector<std::uint32_t>, 2> mark;
    mutable std::array<std::uint32_t, 2> stamp{};
    /// y = sum c_k columnY[j_k] for (j_k, c_k) `terms` (dofs in the factor's order, each column computed): L^-1 b,
    /// its index unsorted. The same bits as long as the terms come in the same order.
    void combine(const std::vector<std::pair<int, double>>& terms, std::size_t s, Sparse& out) const;
    /// Computes the columns of L^-1 of `dofs` (in the factor's order) not computed yet, on the team's threads.
    void computeColumns(const std::vector<int>& dofs, WorkerTeam& team) const;
    /// Forgets the columns (the factor changed).
    void dropColumns() const;
    /// L^-1 e_j per dof j of the factor's order, computed when first needed and kept while the factor stays as it is:
    /// a constraint row or force on a few points is then a sum of their columns instead of a forward solve on its
    /// reach (the contacts touch the same few points step after step). The precomputed surface's are computed with it.
    mutable std::vector<Sparse> columnY;
    mutable std::vector<char> columnReady;
    /// The last step's rows and the constraints' last forces through L^-1 (forwardRows, forwardForced); rowB a row's
    /// entries: (dof in the factor's order, value).
    mutable std::vector<Sparse> rowY;
    mutable std::vector<std::vector<std::pair<int, double>>> rowB;
    mutable Sparse forcedY;
};

void CorotationalFem::Factor::computeColumns(const std::vector<int>& dofs, WorkerTeam& team) const {
    if (columnReady.size() != diag.size()) {
        columnY.assign(diag.size(), {});
        columnReady.assign(diag.size(), 0);
    }
    std::vector<int> missing;
    for (const int j : dofs)
        if (j >= 0 && static_cast<std::size_t>(j) < diag.size() && !columnReady[static_cast<std::size_t>(j)]) {
            columnReady[static_cast<std::size_t>(j)] = 1;
            missing.push_back(j);
        }
    team.run(missing.size(), std::max<std::size_t>(1, (missing.size() + 1) / 2),
             [&](std::size_t chunk, std::size_t begin, std::size_t end) {
                 for (std::size_t i = begin; i < end; ++i)
                     forward({{missing[i], 1.0}}, chunk, columnY[static_cast<std::size_t>(missing[i])]);
             });
}

void CorotationalFem::Factor::dropColumns() const {
    columnY.clear();
    columnReady.clear();
}

void CorotationalFem::Factor::combine(const std::vector<std::pair<int, double>>& terms, std::size_t s,
                                      Sparse& out) const {
    const std::uint32_t now = nextStamp(s);
    std::vector<double>& y = dense[s];
    std::vector<std::uint32_t>& marks = mark[s];
    out.index.clear();
    for (const auto& [column, c] : terms) {
        const Sparse& u = columnY[static_cast<std::size_t>(column)];
        for (std::size_t t = 0; t < u.index.size(); ++t) {
            const auto j = static_cast<std::size_t>(u.index[t]);
            if (marks[j] != now) {
                marks[j] = now;
                out.index.push_back(u.index[t]);
            }
            y[j] += c * u.value[t];
        }
    }
    out.value.resize(out.index.size());
    for (std::size_t k = 0; k < out.index.size(); ++k) {
        out.value[k] = y[static_cast<std::size_t>(out.index[k])];
        y[static_cast<std::size_t>(out.index[k])] = 0.0;
    }
}

std::uint32_t CorotationalFem::Factor::nextStamp(std::size_t s) const {
    const std::size_t dofs = diag.size();
    if (dense[s].size() != dofs || mark[s].size() != dofs) {
        dense[s].assign(dofs, 0.0);
        mark[s].assign(dofs, 0);
        stamp[s] = 0;
    }
    if (++stamp[s] == 0) { // wrapped: clear the marks once every 2^32 calls
        std::fill(mark[s].begin(), mark[s].end(), 0);
        stamp[s] = 1;
    }
    return stamp[s];
}

void CorotationalFem::Factor::forward(const std::vector<std::pair<int, double>>& b, std::size_t s, Sparse& out) const {
    const std::uint32_t now = nextStamp(s);
    std::vector<double>& y = dense[s];
    std::vector<std::uint32_t>& marks = mark[s];
    out.index.clear();
    for (const auto& [dof, entry] : b) {
        for (int j = dof; j >= 0 && marks[static_cast<std::size_t>(j)] != now;
             j = parent[static_cast<std::size_t>(j)]) {
            marks[static_cast<std::size_t>(j)] = now;
            out.index.push_back(j);
        }
        y[static_cast<std::size_t>(dof)] += entry;
    }
    std::sort(out.index.begin(), out.index.end());
    for (const int j : out.index) {
        const double yj = y[static_cast<std::size_t>(j)];
        if (yj == 0.0)
            continue;
        for (int k = colStart[static_cast<std::size_t>(j)]; k < colStart[static_cast<std::size_t>(j) + 1]; ++k)
            y[static_cast<std::size_t>(row[static_cast<std::size_t>(k)])] -= value[static_cast<std::size_t>(k)] * yj;
    }
    out.value.resize(out.index.size());
    for (std::size_t k = 0; k < out.index.size(); ++k) {
        out.value[k] = y[static_cast<std::size_t>(out.index[k])];
        y[static_cast<std::size_t>(out.index[k])] = 0.0;
    }
}

namespace {

using Clock = std::chrono::steady_clock;

/// A row on more points than this (a whole face's load) is not a sum of its points' columns: it takes one forward
/// solve, and its compliance with the others comes from those solves rather than from the surface's block.
constexpr std::size_t kColumnRowPoints = 24;
/// The step's correction sums columns on at most this many points; more take one whole solve.
constexpr std::size_t kColumnCorrectionPoints = 96;
/// The shortest step the search at the volume bound takes (a secant that far back means a residual whose slope along
/// the step jumps: a short step, not none, keeps the tissue moving).
constexpr double kMinBoundStepLength = 0.0625;

double msSince(Clock::time_point t) {
    return std::chrono::duration<double, std::milli>(Clock::now() - t).count();
}

/// |dev e|^2 for the corotated stretch s (e = sym(s) - I).
double deviatoricNorm2(const Mat3& s) {
    const double theta = (s[0] + s[4] + s[8] - 3.0) / 3.0;
    double dev2 = 0.0;
    for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t j = 0; j < 3; ++j) {
            const double e = 0.5 * (s[3 * i + j] + s[3 * j + i]) - (i == j ? 1.0 + theta : 0.0);
            dev2 += e * e;
        }
    return dev2;
}

/// The rest gradients of the tet's four shape functions (rows of Dm^-1 for points 1-3; point 0 their negated sum).
std::array<Vec3, 4> shapeGradients(const Mat3& dmInv) {
    std::array<Vec3, 4> g;
    for (std::size_t a = 0; a < 3; ++a)
        g[a + 1] = {dmInv[3 * a], dmInv[3 * a + 1], dmInv[3 * a + 2]};
    g[0] = (g[1] + g[2] + g[3]) * -1.0;
    return g;
}

/// The isotropic linear stress 2 mu e + lambda tr(e) I of the symmetric part of `s` minus `identity` (0 or 1).
Mat3 linearStress(const Mat3& s, double identity, double mu, double lambda) {
    Mat3 e;
    for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t j = 0; j < 3; ++j)
            e[3 * i + j] = 0.5 * (s[3 * i + j] + s[3 * j + i]) - (i == j ? identity : 0.0);
    const double trace = e[0] + e[4] + e[8];
    for (std::size_t k = 0; k < 9; ++k)
        e[k] *= 2.0 * mu;
    e[0] += lambda * trace;
    e[4] += lambda * trace;
    e[8] += lambda * trace;
    return e;
}

} // namespace

/// A factor rebuilt on its own thread from a copy of what it is built from (startRefactor).
struct CorotationalFem::Rebuild {
    FemSettings settings;
    std::vector<Vec3> rest;
    std::vector<Tet> tets;
    std::vector<std::array<double, 9>> dmInv;
    std::vector<double> volume, mu, lambda;
    std::vector<char> removed;
    std::vector<std::array<bool, 3>> fixed;
    std::vector<double> mass, pointVolume, pointBulk, matrixStiffening, tetherStiffness;
    std::vector<int> partition;
    std::vector<std::int32_t> list;
    std::size_t liveTets = 0;
    std::unique_ptr<Factor> factor;
    std::vector<double> compliance;
    std::thread thread;

    ~Rebuild() {
        if (thread.joinable())
            thread.join();
    }
    void run() {
#if defined(__linux__)
        // The lowest class of the scheduler: the rebuild takes only the time the steps (and the haptics) leave idle,
        // so a step on the shared cores is not held up by it (sched(7), SCHED_IDLE).
        sched_param idle{};
        idle.sched_priority = 0;
        pthread_setschedparam(pthread_self(), SCHED_IDLE, &idle);
#endif
        const FactorInputs in{settings,         rest,           tets,  dmInv, volume,      mu,
                              lambda,           removed,        fixed, mass,  pointVolume, pointBulk,
                              matrixStiffening, tetherStiffness};
        factor = std::make_unique<Factor>();
        buildFactor(in, partition, *factor);
        if (!list.empty()) {
            WorkerTeam team(1);
            precomputeInto(*factor, list, fixed, team, compliance);
        }
    }
};

CorotationalFem::CorotationalFem() = default;
CorotationalFem::~CorotationalFem() = default;
CorotationalFem::CorotationalFem(CorotationalFem&&) noexcept = default;
CorotationalFem& CorotationalFem::operator=(CorotationalFem&&) noexcept = default;

Status CorotationalFem::build(const std::vector<Vec3>& pointsM, const std::vector<Tet>& tets,
                              const std::vector<FemMaterial>& materials,
                              const std::vector<std::array<bool, 3>>& fixedDof,
                              const std::vector<std::pair<std::int32_t, double>>& tethers,
                              const FemSettings& settings) {
    if (!(settings.stepS > 0.0 && settings.stepS <= 10.0) || settings.iterations < 1 || settings.iterations > 50 ||
        !(settings.rayleighMassPerS >= 0.0) || !(settings.rayleighStiffnessS >= 0.0) || settings.contactSweeps < 1 ||
        !(settings.tetPressureShare >= 0.0 && settings.tetPressureShare <= 1.0) || settings.threads < 1 ||
        settings.threads > 64)
        return fail(ErrorCode::InvalidInput, "tissue solver: step 0-10 s, iterations 1-50, damping >= 0");
    const std::size_t n = pointsM.size();
    if (materials.size() != tets.size() || fixedDof.size() != n)
        return fail(ErrorCode::InvalidInput, "tissue solver: one material per tet and one fixed flag per point");
    m_rebuild.reset(); // a rebuild of the old mesh
    m_settings = settings;
    m_partition.clear(); // a new mesh: the factor's halves are cut anew
    m_rest = pointsM;
    m_x = pointsM;
    m_target = pointsM;
    m_v.assign(n, Vec3{});
    m_reaction.assign(n, Vec3{});
    m_constraintForce.assign(n, Vec3{});
    m_forcedPoints.clear();
    m_fixed = fixedDof;
    m_tets = tets;
    m_materials = materials;
    m_tethers = tethers;
    m_removed.assign(tets.size(), 0);
    m_mass.assign(n, 0.0);
    m_dmInv.resize(tets.size());
    m_volume.resize(tets.size());
    m_restDet.resize(tets.size());
    m_mu.resize(tets.size());
    m_lambda.resize(tets.size());
    m_rotation.assign(tets.size(), {1.0, 0.0, 0.0, 0.0});
    for (std::size_t t = 0; t < tets.size(); ++t) {
        const Tet& tet = tets[t];
        for (const std::int32_t p : tet)
            if (p < 0 || static_cast<std::size_t>(p) >= n)
                return fail(ErrorCode::InvalidInput,
                            "tissue solver: tet " + std::to_string(t) + " has a point out of range");
        const FemMaterial& m = materials[t];
        if (!(m.youngsModulusPa > 0.0) || !(m.poissonRatio >= 0.0 && m.poissonRatio < 0.5) || !(m.densityKgPerM3 > 0.0))
            return fail(ErrorCode::InvalidInput, "tissue solver: tet " + std::to_string(t) +
                                                     ": Young's modulus > 0, Poisson ratio 0-0.5, density > 0");
        const Mat3 dm =
            shapeMatrix(pointsM[static_cast<std::size_t>(tet[0])], pointsM[static_cast<std::size_t>(tet[1])],
                        pointsM[static_cast<std::size_t>(tet[2])], pointsM[static_cast<std::size_t>(tet[3])]);
        double det = 0.0;
        if (!invert(dm, m_dmInv[t], det) || std::abs(det) < 1e-24)
            return fail(ErrorCode::InvalidInput, "tissue solver: tet " + std::to_string(t) + " is flat");
        m_volume[t] = std::abs(det) / 6.0;
        m_restDet[t] = det;
        m_mu[t] = m.youngsModulusPa / (2.0 * (1.0 + m.poissonRatio));
        m_lambda[t] = m.youngsModulusPa * m.poissonRatio / ((1.0 + m.poissonRatio) * (1.0 - 2.0 * m.poissonRatio));
        for (const std::int32_t p : tet)
            m_mass[static_cast<std::size_t>(p)] += m.densityKgPerM3 * m_volume[t] / 4.0;
    }
    m_tetherStiffness.assign(n, 0.0);
    for (const auto& [p, k] : tethers) {
        if (p < 0 || static_cast<std::size_t>(p) >= n || !(k >= 0.0) || !std::isfinite(k))
            return fail(ErrorCode::InvalidInput, "tissue solver: a tether's point or stiffness is out of range");
        m_tetherStiffness[static_cast<std::size_t>(p)] += k;
    }
    m_pointVolume.assign(n, 0.0);
    m_pointBulk.assign(n, 0.0);
    for (std::size_t t = 0; t < tets.size(); ++t)
        for (const std::int32_t p : tets[t]) {
            m_pointVolume[static_cast<std::size_t>(p)] += m_volume[t] / 4.0;
            m_pointBulk[static_cast<std::size_t>(p)] += (m_lambda[t] + 2.0 * m_mu[t] / 3.0) * m_volume[t] / 4.0;
        }
    for (std::size_t i = 0; i < n; ++i)
        if (m_pointVolume[i] > 0.0)
            m_pointBulk[i] /= m_pointVolume[i];
    for (std::size_t i = 0; i < n; ++i)
        if (!(m_mass[i] > 0.0))
            m_mass[i] = 1e-12; // a point of no tet: it keeps the matrix definite and never moves
    m_compliantIndex.assign(n, -1);
    m_compliance.clear();
    m_compliantCount = 0;
    m_complianceStale = false;
    buildIncidence();
    m_neighbours.assign(tets.size(), {-1, -1, -1, -1});
    {
        std::vector<std::pair<std::array<std::int32_t, 3>, std::uint32_t>> faces; // (sorted face, 4 tet + face)
        faces.reserve(4 * tets.size());
        for (std::size_t t = 0; t < tets.size(); ++t)
            for (std::uint32_t k = 0; k < 4; ++k)
                faces.push_back({sortedFace(tets[t][static_cast<std::size_t>(kTetFacePoints[k][0])],
                                            tets[t][static_cast<std::size_t>(kTetFacePoints[k][1])],
                                            tets[t][static_cast<std::size_t>(kTetFacePoints[k][2])]),
                                 static_cast<std::uint32_t>(4 * t + k)});
        std::sort(faces.begin(), faces.end());
        for (std::size_t i = 1; i < faces.size(); ++i)
            if (faces[i].first == faces[i - 1].first) {
                const std::uint32_t a = faces[i - 1].second, b = faces[i].second;
                m_neighbours[a / 4][a % 4] = static_cast<std::int32_t>(b / 4);
                m_neighbours[b / 4][b % 4] = static_cast<std::int32_t>(a / 4);
            }
    }
    m_liveTets = tets.size();
    m_factorStale = false;
    assembleAndFactor();
    return {};
}

Status CorotationalFem::buildLike(const CorotationalFem& other, const FemSettings& settings) {
    if (this == &other)
        return fail(ErrorCode::InvalidInput, "tissue solver: a model cannot be built like itself");
    HS_TRY(build(other.m_rest, other.m_tets, other.m_materials, other.m_fixed, other.m_tethers, settings));
    m_removed = other.m_removed;
    m_liveTets = other.m_liveTets;
    if (m_liveTets != m_tets.size())
        updatePointMeasures();
    assembleAndFactor();
    return {};
}

namespace {

/// The entries of L for `block` in its AMD order, from the symbolic analysis alone (the elimination tree's column
/// counts): what the numeric factorization would store, without computing it.
std::size_t symbolicFill(const Eigen::SparseMatrix<double>& block) {
    struct Symbolic : Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower, Eigen::AMDOrdering<int>> {
        std::size_t fill(const Eigen::SparseMatrix<double>& a) {
            analyzePattern(a);
            return static_cast<std::size_t>(m_matrix.nonZeros());
        }
    };
    return Symbolic{}.fill(block);
}

} // namespace

void CorotationalFem::buildFactor(const FactorInputs& in, std::vector<int>& partition, Factor& f) {
    const std::size_t n = in.rest.size();
    const double h = in.settings.stepS;
    const double stiffnessScale = 1.0 + in.settings.rayleighStiffnessS / h;
    const double massScale = 1.0 / (h * h) + in.settings.rayleighMassPerS / h;
    const auto heldDof = [&in](std::size_t dof) { return in.fixed[dof / 3][dof % 3]; };
    std::vector<Eigen::Triplet<double>> triplets;
    triplets.reserve(in.tets.size() * 144 + 3 * n);
    const bool nodal = in.settings.nodalPressure && in.settings.nodalPressureMatrix;
    for (std::size_t t = 0; t < in.tets.size(); ++t) {
        if (in.removed[t])
            continue;
        const std::array<Vec3, 4> g = shapeGradients(in.dmInv[t]);
        // With nodal pressure the tet keeps only its deviatoric part (lambda -> -2 mu / 3); the volumetric part is
        // assembled per point below.
        // The deviatoric part at the tet's tangent stiffening (1 at rest: refactorStiffened() sets it).
        const double share = in.settings.tetPressureShare, bulk = in.lambda[t] + 2.0 * in.mu[t] / 3.0;
        const double v = in.volume[t] * stiffnessScale;
        const double mu = in.mu[t] * (in.matrixStiffening.empty() ? 1.0 : in.matrixStiffening[t]);
        const double la = -2.0 * mu / 3.0 + (nodal ? share * bulk : bulk);
        for (std::size_t a = 0; a < 4; ++a)
            for (std::size_t b = 0; b < 4; ++b) {
                const double gg = dot(g[a], g[b]);
                for (int i = 0; i < 3; ++i)
                    for (int j = 0; j < 3; ++j) {
                        const auto row = static_cast<std::size_t>(3 * in.tets[t][a] + i);
                        const auto col = static_cast<std::size_t>(3 * in.tets[t][b] + j);
                        if (heldDof(row) || heldDof(col))
                            continue;
                        const double k =
                            v * (la * g[a][i] * g[b][j] + mu * g[a][j] * g[b][i] + (i == j ? mu * gg : 0.0));
                        triplets.emplace_back(static_cast<int>(row), static_cast<int>(col), k);
                    }
            }
    }
    if (nodal) {
        // Per point n: kappa_n V_n b_n b_n^T, with b_n the gradient of its averaged dilatation
        // theta_n = sum over its tets of (V_t / 4 V_n) theta_t.
        std::vector<std::vector<std::size_t>> tetsOf(n);
        for (std::size_t t = 0; t < in.tets.size(); ++t)
            if (!in.removed[t])
                for (const std::int32_t p : in.tets[t])
                    tetsOf[static_cast<std::size_t>(p)].push_back(t);
        std::vector<std::pair<std::size_t, Vec3>> gradient; // (point, d theta_n / d x_point)
        for (std::size_t p = 0; p < n; ++p) {
            if (tetsOf[p].empty() || !(in.pointVolume[p] > 0.0))
                continue;
            gradient.clear();
            for (const std::size_t t : tetsOf[p]) {
                const std::array<Vec3, 4> g = shapeGradients(in.dmInv[t]);
                for (std::size_t a = 0; a < 4; ++a) {
                    const auto q = static_cast<std::size_t>(in.tets[t][a]);
                    const Vec3 add = g[a] * (in.volume[t] / (4.0 * in.pointVolume[p]));
                    auto it = std::find_if(gradient.begin(), gradient.end(),
                                           [q](const std::pair<std::size_t, Vec3>& e) { return e.first == q; });
                    if (it == gradient.end())
                        gradient.emplace_back(q, add);
                    else
                        it->second += add;
                }
            }
            const double scale =
                (1.0 - in.settings.tetPressureShare) * in.pointBulk[p] * in.pointVolume[p] * stiffnessScale;
            for (const auto& [qa, ga] : gradient)
                for (const auto& [qb, gb] : gradient)
                    for (int i = 0; i < 3; ++i)
                        for (int j = 0; j < 3; ++j) {
                            const std::size_t row = 3 * qa + static_cast<std::size_t>(i);
                            const std::size_t col = 3 * qb + static_cast<std::size_t>(j);
                            if (heldDof(row) || heldDof(col))
                                continue;
                            triplets.emplace_back(static_cast<int>(row), static_cast<int>(col), scale * ga[i] * gb[j]);
                        }
        }
    }
    for (std::size_t dof = 0; dof < 3 * n; ++dof) {
        const double d = heldDof(dof) ? 1.0 : in.mass[dof / 3] * massScale + in.tetherStiffness[dof / 3];
        triplets.emplace_back(static_cast<int>(dof), static_cast<int>(dof), d);
    }
    Eigen::SparseMatrix<double> h3(static_cast<Eigen::Index>(3 * n), static_cast<Eigen::Index>(3 * n));
    h3.setFromTriplets(triplets.begin(), triplets.end());
    // The points' neighbours in the matrix.
    std::vector<std::vector<std::int32_t>> neighbours(n);
    for (Eigen::Index c = 0; c < h3.outerSize(); ++c)
        for (Eigen::SparseMatrix<double>::InnerIterator it(h3, c); it; ++it) {
            const auto a = static_cast<std::size_t>(it.row()) / 3, b = static_cast<std::size_t>(c) / 3;
            if (a != b)
                neighbours[a].push_back(static_cast<std::int32_t>(b));
        }
    // The two halves: the points by their rest place along the longest side of the mesh's box, cut where the halves'
    // factors hold about as many entries (bisected on the cut's place); the separator: the first half's points next
    // to the second's.
    Vec3 lo = n > 0 ? in.rest[0] : Vec3{}, hi = lo;
    for (const Vec3& p : in.rest)
        for (int d = 0; d < 3; ++d) {
            lo[d] = std::min(lo[d], p[d]);
            hi[d] = std::max(hi[d], p[d]);
        }
    int axis = 0;
    for (int d = 1; d < 3; ++d)
        if (hi[d] - lo[d] > hi[axis] - lo[axis])
            axis = d;
    std::vector<std::int32_t> byPlace(n);
    for (std::size_t i = 0; i < n; ++i)
        byPlace[i] = static_cast<std::int32_t>(i);
    std::sort(byPlace.begin(), byPlace.end(), [&in, axis](std::int32_t a, std::int32_t b) {
        const double pa = in.rest[static_cast<std::size_t>(a)][axis], pb = in.rest[static_cast<std::size_t>(b)][axis];
        return pa < pb || (pa == pb && a < b);
    });
    const auto cutAt = [&](std::size_t first) {
        std::vector<int> part(n, 1); // 0, 1: the halves; 2: the separator
        for (std::size_t k = 0; k < first; ++k)
            part[static_cast<std::size_t>(byPlace[k])] = 0;
        for (std::size_t i = 0; i < n; ++i)
            if (part[i] == 0)
                for (const std::int32_t j : neighbours[i])
                    if (part[static_cast<std::size_t>(j)] == 1) {
                        part[i] = 2;
                        break;
                    }
        return part;
    };
    // A part's dofs in its own AMD order (Eigen's ordering gives the old index at each new place), and its factor's
    // entries when `fill` is asked for.
    const auto partOrder = [&](const std::vector<int>& part, int which, std::size_t* fill) {
        std::vector<int> dofs;
        for (std::size_t i = 0; i < n; ++i)
            if (part[i] == which)
                for (int d = 0; d < 3; ++d)
                    dofs.push_back(static_cast<int>(3 * i) + d);
        std::vector<int> local(3 * n, -1);
        for (std::size_t k = 0; k < dofs.size(); ++k)
            local[static_cast<std::size_t>(dofs[k])] = static_cast<int>(k);
        std::vector<Eigen::Triplet<double>> sub;
        for (const int dof : dofs)
            for (Eigen::SparseMatrix<double>::InnerIterator it(h3, dof); it; ++it)
                if (local[static_cast<std::size_t>(it.row())] >= 0)
                    sub.emplace_back(local[static_cast<std::size_t>(it.row())], local[static_cast<std::size_t>(dof)],
                                     it.value());
        Eigen::SparseMatrix<double> block(static_cast<Eigen::Index>(dofs.size()),
                                          static_cast<Eigen::Index>(dofs.size()));
        block.setFromTriplets(sub.begin(), sub.end());
        std::vector<int> order;
        if (dofs.empty())
            return order;
        Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> amd;
        Eigen::AMDOrdering<int>()(block, amd);
        for (std::size_t k = 0; k < dofs.size(); ++k)
            order.push_back(dofs[static_cast<std::size_t>(amd.indices()[static_cast<Eigen::Index>(k)])]);
        if (fill)
            *fill = symbolicFill(block);
        return order;
    };
    if (partition.size() != n) {
        std::size_t low = 3 * n / 10, high = 7 * n / 10;
        for (int step = 0; step < 8 && low + 1 < high; ++step) {
            const std::size_t mid = (low + high) / 2;
            const std::vector<int> part = cutAt(mid);
            std::size_t fillA = 0, fillB = 0;
            partOrder(part, 0, &fillA);
            partOrder(part, 1, &fillB);
            (fillA < fillB ? low : high) = mid;
        }
        partition = cutAt((low + high) / 2);
    }
    std::vector<int> newToOld;
    newToOld.reserve(3 * n);
    for (int which = 0; which < 3; ++which) {
        const std::vector<int> order = partOrder(partition, which, nullptr);
        newToOld.insert(newToOld.end(), order.begin(), order.end());
        if (which < 2)
            f.partEnd[static_cast<std::size_t>(which)] = newToOld.size();
    }
    f.oldToNew.assign(3 * n, 0);
    for (std::size_t k = 0; k < newToOld.size(); ++k)
        f.oldToNew[static_cast<std::size_t>(newToOld[k])] = static_cast<int>(k);
    std::vector<Eigen::Triplet<double>> permuted;
    permuted.reserve(static_cast<std::size_t>(h3.nonZeros()));
    for (Eigen::Index c = 0; c < h3.outerSize(); ++c)
        for (Eigen::SparseMatrix<double>::InnerIterator it(h3, c); it; ++it)
            permuted.emplace_back(f.oldToNew[static_cast<std::size_t>(it.row())],
                                  f.oldToNew[static_cast<std::size_t>(c)], it.value());
    Eigen::SparseMatrix<double> ordered(h3.rows(), h3.cols());
    ordered.setFromTriplets(permuted.begin(), permuted.end());
    f.ldlt.compute(ordered);
    // L's strictly lower part and D, for the two-part solve.
    const auto& l = f.ldlt.matrixL().nestedExpression();
    f.colStart.assign(3 * n + 1, 0);
    f.row.clear();
    f.value.clear();
    for (Eigen::Index c = 0; c < l.outerSize(); ++c) {
        for (std::remove_reference_t<decltype(l)>::InnerIterator it(l, c); it; ++it)
            if (it.row() > c) {
                f.row.push_back(static_cast<int>(it.row()));
                f.value.push_back(it.value());
            }
        f.colStart[static_cast<std::size_t>(c) + 1] = static_cast<int>(f.row.size());
    }
    const Eigen::VectorXd d = f.ldlt.vectorD();
    f.diag.assign(d.data(), d.data() + d.size());
    f.dropColumns();
    f.parent.assign(3 * n, -1);
    for (std::size_t c = 0; c < 3 * n; ++c)
        for (int k = f.colStart[c]; k < f.colStart[c + 1]; ++k) {
            int& first = f.parent[c];
            const int r = f.row[static_cast<std::size_t>(k)];
            first = first < 0 ? r : std::min(first, r);
        }
    f.work.assign(3 * n, 0.0);
}

CorotationalFem::FactorInputs CorotationalFem::factorInputs() const {
    return {m_settings,         m_rest,           m_tets,  m_dmInv, m_volume,      m_mu,
            m_lambda,           m_removed,        m_fixed, m_mass,  m_pointVolume, m_pointBulk,
            m_matrixStiffening, m_tetherStiffness};
}

void CorotationalFem::assembleAndFactor() {
    auto factor = std::make_unique<Factor>();
    buildFactor(factorInputs(), m_partition, *factor);
    m_factor = std::move(factor);
    m_factorPointVolume = m_pointVolume;
    m_factorFixed = m_fixed;
    if (!m_team || m_team->size() != std::max(1, m_settings.threads))
        m_team = std::make_unique<WorkerTeam>(std::max(1, m_settings.threads));
}

void CorotationalFem::setTarget(std::size_t point, const Vec3& positionM) {
    if (point < m_target.size())
        m_target[point] = positionM;
}

void CorotationalFem::buildIncidence() {
    // Each point's tets (with the point's corner in each), in increasing tet order: the gathers below add in the
    // order a serial scatter over the tets would, so every thread count gives the same bits.
    const std::size_t n = m_x.size();
    m_incidenceStart.assign(n + 1, 0);
    for (const Tet& tet : m_tets)
        for (const std::int32_t p : tet)
            ++m_incidenceStart[static_cast<std::size_t>(p) + 1];
    for (std::size_t i = 0; i < n; ++i)
        m_incidenceStart[i + 1] += m_incidenceStart[i];
    m_incidence.assign(m_incidenceStart[n], {0, 0});
    std::vector<std::size_t> fill(m_incidenceStart.begin(), m_incidenceStart.end() - 1);
    for (std::size_t t = 0; t < m_tets.size(); ++t)
        for (std::uint32_t k = 0; k < 4; ++k)
            m_incidence[fill[static_cast<std::size_t>(m_tets[t][k])]++] = {static_cast<std::uint32_t>(t), k};
}

void CorotationalFem::internalForces(const std::vector<Vec3>& x, const std::vector<Vec3>& v, std::vector<Vec3>& out) {
    const auto started = Clock::now();
    const std::size_t n = x.size();
    out.assign(n, Vec3{});
    const double beta = m_settings.rayleighStiffnessS;
    const bool nodal = m_settings.nodalPressure;
    const std::size_t tets = m_tets.size();
    const int threads = std::max(1, m_settings.threads);
    if (!m_team || m_team->size() != threads)
        m_team = std::make_unique<WorkerTeam>(threads);
    const int pieces = 4 * threads; // taken as they come: a helper late to a pass leaves its share to the other
    m_tetR.resize(tets);
    m_tetDilatation.assign(tets, 0.0);
    m_tetRate.assign(tets, 0.0);
    m_tetStrain.resize(tets);
    m_tetStrainRate.resize(tets);
    m_tetForces.resize(tets);
    // Pass 1 (tets): each tet's rotation, its corotated strain and strain rate.
    m_team->run(tets, evenChunk(tets, pieces), [&](std::size_t, std::size_t begin, std::size_t end) {
        for (std::size_t t = begin; t < end; ++t) {
            if (m_removed[t])
                continue;
            const Tet& tet = m_tets[t];
            const auto p = [&tet](std::size_t k) { return static_cast<std::size_t>(tet[k]); };
            const Mat3& dmInv = m_dmInv[t];
            const Mat3 f = multiply(shapeMatrix(x[p(0)], x[p(1)], x[p(2)], x[p(3)]), dmInv);
            m_tetR[t] = rotationOf(f, m_rotation[t], 3);
            m_tetStrain[t] = multiplyTransposed(m_tetR[t], f);
            m_tetDilatation[t] = m_tetStrain[t][0] + m_tetStrain[t][4] + m_tetStrain[t][8] - 3.0;
            if (beta > 0.0) {
                const Mat3 l = multiply(shapeMatrix(v[p(0)], v[p(1)], v[p(2)], v[p(3)]), dmInv);
                m_tetStrainRate[t] = multiplyTransposed(m_tetR[t], l);
                m_tetRate[t] = m_tetStrainRate[t][0] + m_tetStrainRate[t][4] + m_tetStrainRate[t][8];
            }
        }
    });
    // Pass 2 (points): the averaged dilatation and each point's rotation.
    if (nodal) {
        m_pointDilatation.assign(n, 0.0);
        m_pointRate.assign(n, 0.0);
    }
    m_pointR.assign(n, Mat3{1, 0, 0, 0, 1, 0, 0, 0, 1});
    m_pointQuat.resize(n, {1.0, 0.0, 0.0, 0.0});
    m_team->run(n, evenChunk(n, pieces), [&](std::size_t, std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i) {
            Mat3 sum{};
            bool any = false;
            for (std::size_t k = m_incidenceStart[i]; k < m_incidenceStart[i + 1]; ++k) {
                const std::size_t t = m_incidence[k].first;
                if (m_removed[t])
                    continue;
                any = true;
                if (nodal) {
                    const double w = m_volume[t] / (4.0 * m_pointVolume[i]);
                    m_pointDilatation[i] += w * m_tetDilatation[t];
                    m_pointRate[i] += w * m_tetRate[t];
                }
                for (std::size_t c = 0; c < 9; ++c)
                    sum[c] += m_volume[t] * m_tetR[t][c];
            }
            if (any && !m_fixed[i][0] && !m_fixed[i][1] && !m_fixed[i][2])
                m_pointR[i] = rotationOf(sum, m_pointQuat[i], 4);
        }
    });
    // Pass 3 (tets): stresses and each corner's force.
    m_team->run(tets, evenChunk(tets, pieces), [&](std::size_t, std::size_t begin, std::size_t end) {
        for (std::size_t t = begin; t < end; ++t) {
            if (m_removed[t])
                continue;
            const Tet& tet = m_tets[t];
            const auto p = [&tet](std::size_t k) { return static_cast<std::size_t>(tet[k]); };
            const Mat3& dmInv = m_dmInv[t];
            const double mu = m_mu[t];
            double pressure = 0.0, pressureRate = 0.0; // the volumetric stress, and its rate's
            if (nodal) {
                const double share = m_settings.tetPressureShare, bulk = m_lambda[t] + 2.0 * mu / 3.0;
                for (std::size_t k = 0; k < 4; ++k) {
                    pressure += 0.25 * (1.0 - share) * m_pointBulk[p(k)] * m_pointDilatation[p(k)];
                    pressureRate += 0.25 * (1.0 - share) * m_pointBulk[p(k)] * m_pointRate[p(k)];
                }
                pressure += share * bulk * m_tetDilatation[t];
                pressureRate += share * bulk * m_tetRate[t];
            } else {
                const double bulk = m_lambda[t] + 2.0 * mu / 3.0;
                pressure = bulk * m_tetDilatation[t];
                pressureRate = bulk * m_tetRate[t];
            }
            // sigma = 2 mu s dev(e) + pressure I (s: the exponential stiffening's secant factor, 1 for a linear
            // tet), and beta times the same of the strain rate.
            const double s = stiffening(t, m_tetStrain[t]);
            Mat3 sigma = linearStress(m_tetStrain[t], 1.0, mu * s, -2.0 * mu / 3.0 * s);
            sigma[0] += pressure;
            sigma[4] += pressure;
            sigma[8] += pressure;
            if (beta > 0.0) {
                const Mat3 damping = linearStress(m_tetStrainRate[t], 0.0, mu, -2.0 * mu / 3.0);
                for (std::size_t k = 0; k < 9; ++k)
                    sigma[k] += beta * damping[k];
                sigma[0] += beta * pressureRate;
                sigma[4] += beta * pressureRate;
                sigma[8] += beta * pressureRate;
            }
            const Mat3 piola = multiply(m_tetR[t], sigma);
            // f_a = -V P g_a with g_a the rows of Dm^-1: the columns of -V P Dm^-T; corner 0 takes minus their sum.
            Vec3 sum{};
            for (std::size_t a = 0; a < 3; ++a) {
                const Vec3 g{dmInv[3 * a], dmInv[3 * a + 1], dmInv[3 * a + 2]};
                const Vec3 fa = Vec3{piola[0] * g.x + piola[1] * g.y + piola[2] * g.z,
                                     piola[3] * g.x + piola[4] * g.y + piola[5] * g.z,
                                     piola[6] * g.x + piola[7] * g.y + piola[8] * g.z} *
                                -m_volume[t];
                m_tetForces[t][a + 1] = fa;
                sum += fa;
            }
            m_tetForces[t][0] = sum * -1.0;
        }
    });
    // Pass 4 (points): each point's force, its tets' corners in tet order.
    m_team->run(n, evenChunk(n, pieces), [&](std::size_t, std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i)
            for (std::size_t k = m_incidenceStart[i]; k < m_incidenceStart[i + 1]; ++k) {
                const std::size_t t = m_incidence[k].first;
                if (!m_removed[t])
                    out[i] += m_tetForces[t][m_incidence[k].second];
            }
    });
    m_timings.forcesMs += msSince(started);
}

void CorotationalFem::solveWith(const Factor& f, const std::vector<std::array<bool, 3>>& fixed, WorkerTeam& team,
                                std::vector<double>& b) {
    for (std::size_t dof = 0; dof < b.size(); ++dof)
        if (fixed[dof / 3][dof % 3])
            b[dof] = 0.0;
    const std::size_t dofs = f.oldToNew.size();
    std::vector<double>& y = f.work;
    for (std::size_t i = 0; i < dofs; ++i)
        y[static_cast<std::size_t>(f.oldToNew[i])] = b[i];
    const std::size_t sep = f.partEnd[1];
    const std::array<std::size_t, 3> begin{0, f.partEnd[0], f.partEnd[1]};
    const std::array<std::size_t, 3> end{f.partEnd[0], f.partEnd[1], dofs};
    // L y = b: the halves side by side, the separator's rows gathered per half.
    team.run(2, 1, [&](std::size_t half, std::size_t, std::size_t) {
        std::vector<double>& buffer = f.buffer[half];
        buffer.assign(dofs - sep, 0.0);
        for (std::size_t j = begin[half]; j < end[half]; ++j) {
            const double yj = y[j];
            for (int k = f.colStart[j]; k < f.colStart[j + 1]; ++k) {
                const auto r = static_cast<std::size_t>(f.row[static_cast<std::size_t>(k)]);
                if (r < sep)
                    y[r] -= f.value[static_cast<std::size_t>(k)] * yj;
                else
                    buffer[r - sep] += f.value[static_cast<std::size_t>(k)] * yj;
            }
        }
    });
    for (std::size_t r = sep; r < dofs; ++r)
        y[r] = (y[r] - f.buffer[0][r - sep]) - f.buffer[1][r - sep];
    for (std::size_t j = sep; j < dofs; ++j)
        for (int k = f.colStart[j]; k < f.colStart[j + 1]; ++k)
            y[static_cast<std::size_t>(f.row[static_cast<std::size_t>(k)])] -=
                f.value[static_cast<std::size_t>(k)] * y[j];
    for (std::size_t j = 0; j < dofs; ++j)
        y[j] /= f.diag[j];
    backwardWith(f, team, y);
    for (std::size_t i = 0; i < dofs; ++i)
        b[i] = y[static_cast<std::size_t>(f.oldToNew[i])];
}

void CorotationalFem::backwardWith(const Factor& f, WorkerTeam& team, std::vector<double>& y) {
    // L^T x = y: the separator first, then the halves side by side.
    const std::size_t dofs = f.oldToNew.size(), sep = f.partEnd[1];
    const std::array<std::size_t, 3> begin{0, f.partEnd[0], f.partEnd[1]};
    const std::array<std::size_t, 3> end{f.partEnd[0], f.partEnd[1], dofs};
    for (std::size_t j = dofs; j-- > sep;)
        for (int k = f.colStart[j]; k < f.colStart[j + 1]; ++k)
            y[j] -=
                f.value[static_cast<std::size_t>(k)] * y[static_cast<std::size_t>(f.row[static_cast<std::size_t>(k)])];
    team.run(2, 1, [&](std::size_t half, std::size_t, std::size_t) {
        for (std::size_t j = end[half]; j-- > begin[half];)
            for (int k = f.colStart[j]; k < f.colStart[j + 1]; ++k)
                y[j] -= f.value[static_cast<std::size_t>(k)] *
                        y[static_cast<std::size_t>(f.row[static_cast<std::size_t>(k)])];
    });
}

void CorotationalFem::solveInPlace(std::vector<double>& b) const {
    const auto started = Clock::now();
    solveWith(*m_factor, m_fixed, *m_team, b);
    // A dof held since the factor (a point a removal left without a tet) is held still.
    if (m_factorStale)
        for (std::size_t dof = 0; dof < b.size(); ++dof)
            if (m_fixed[dof / 3][dof % 3])
                b[dof] = 0.0;
    m_timings.solveMs += msSince(started);
}

void CorotationalFem::solveWarped(std::vector<double>& b) const {
    const std::size_t n = m_x.size();
    const bool warped = m_pointR.size() == n;
    if (warped)
        for (std::size_t i = 0; i < n; ++i) {
            const Mat3& r = m_pointR[i];
            const double x = b[3 * i], y = b[3 * i + 1], z = b[3 * i + 2];
            b[3 * i] = r[0] * x + r[3] * y + r[6] * z;
            b[3 * i + 1] = r[1] * x + r[4] * y + r[7] * z;
            b[3 * i + 2] = r[2] * x + r[5] * y + r[8] * z;
        }
    solveInPlace(b);
    if (warped)
        for (std::size_t i = 0; i < n; ++i) {
            const Mat3& r = m_pointR[i];
            const double x = b[3 * i], y = b[3 * i + 1], z = b[3 * i + 2];
            b[3 * i] = r[0] * x + r[1] * y + r[2] * z;
            b[3 * i + 1] = r[3] * x + r[4] * y + r[5] * z;
            b[3 * i + 2] = r[6] * x + r[7] * y + r[8] * z;
        }
}

void CorotationalFem::precomputeCompliance(const std::vector<std::int32_t>& points) {
    m_rebuild.reset(); // it would bring back the surface it began with
    m_volumeRowPointsAdded = 0;
    const std::size_t n = m_x.size();
    m_compliantIndex.assign(n, -1);
    std::vector<std::int32_t> list;
    for (const std::int32_t p : points)
        if (p >= 0 && static_cast<std::size_t>(p) < n && m_compliantIndex[static_cast<std::size_t>(p)] < 0) {
            m_compliantIndex[static_cast<std::size_t>(p)] = static_cast<std::int32_t>(list.size());
            list.push_back(p);
        }
    m_compliantCount = list.size();
    m_compliantList = list;
    precomputeInto(*m_factor, m_compliantList, m_fixed, *m_team, m_compliance);
    m_complianceStride = 3 * m_compliantCount;
    m_complianceStale = false;
    m_staleNear.assign(n, 0);
    m_refreshPoint = 0;
    m_refreshDof = 0;
}

bool CorotationalFem::precomputedAt(std::size_t p) const {
    return m_compliantIndex[p] >= 0 && (!m_complianceStale || (p < m_staleNear.size() && !m_staleNear[p]));
}

void CorotationalFem::extendPrecomputedSurface(const std::vector<std::int32_t>& points) {
    if (m_compliantCount == 0 || !m_factor)
        return;
    std::vector<std::int32_t> added;
    for (const std::int32_t p : points)
        if (p >= 0 && static_cast<std::size_t>(p) < m_x.size() && m_compliantIndex[static_cast<std::size_t>(p)] < 0 &&
            std::find(added.begin(), added.end(), p) == added.end())
            added.push_back(p);
    if (added.empty())
        return;
    const std::size_t m3 = 3 * (m_compliantCount + added.size());
    if (m3 > m_complianceStride) {
        // Room for this many more points at once: growing copies the whole block.
        constexpr std::size_t kGrowPoints = 64;
        const std::size_t stride = m3 + 3 * kGrowPoints, old = 3 * m_compliantCount;
        std::vector<double> grown(stride * stride, 0.0);
        for (std::size_t r = 0; r < old; ++r)
            std::copy_n(&m_compliance[r * m_complianceStride], old, &grown[r * stride]);
        m_compliance = std::move(grown);
        m_complianceStride = stride;
    }
    m_staleNear.resize(m_x.size(), 0);
    for (const std::int32_t p : added) {
        m_compliantIndex[static_cast<std::size_t>(p)] = static_cast<std::int32_t>(m_compliantCount++);
        m_compliantList.push_back(p);
        m_staleNear[static_cast<std::size_t>(p)] = 1; // its columns are computed by the refresh; until then it solves
    }
    m_complianceStale = true;
}

void CorotationalFem::refreshStaleSurface(int dofs) {
    if (!m_complianceStale || m_compliantCount == 0)
        return;
    const auto started = Clock::now();
    const std::size_t m = m_compliantCount;
    std::vector<double> column;
    while (dofs > 0) {
        // The next point near a cut, from the cursor on (round the list once).
        std::size_t k = m_refreshPoint % m, looked = 0;
        while (looked < m && !m_staleNear[static_cast<std::size_t>(m_compliantList[k])]) {
            k = (k + 1) % m;
            m_refreshDof = 0;
            ++looked;
        }
        if (looked == m) {
            m_complianceStale = false; // every point near a cut has its columns of the factor in use again
            break;
        }
        m_refreshPoint = k;
        const auto p = static_cast<std::size_t>(m_compliantList[k]);
        const std::size_t d = m_refreshDof;
        // H^-1 e: L^-1 e is the dof's column of L^-1, non-zero on its reach only (kept per factor), then D^-1 and
        // the whole backward solve, in the factor's order.
        const Factor& f = *m_factor;
        column.assign(3 * m_x.size(), 0.0);
        if (!m_fixed[p][d]) {
            const int dof = f.oldToNew[3 * p + d];
            f.computeColumns({dof}, *m_team);
            const Factor::Sparse& y = f.columnY[static_cast<std::size_t>(dof)];
            for (std::size_t t = 0; t < y.index.size(); ++t)
                column[static_cast<std::size_t>(y.index[t])] =
                    y.value[t] / f.diag[static_cast<std::size_t>(y.index[t])];
            backwardWith(f, *m_team, column);
        }
        for (std::size_t j = 0; j < m; ++j)
            for (std::size_t e = 0; e < 3; ++e) {
                const auto q = static_cast<std::size_t>(m_compliantList[j]);
                const double c = m_fixed[q][e] ? 0.0 : column[static_cast<std::size_t>(f.oldToNew[3 * q + e])];
                m_compliance[(3 * j + e) * m_complianceStride + 3 * k + d] = c;
                m_compliance[(3 * k + d) * m_complianceStride + 3 * j + e] = c;
            }
        if (++m_refreshDof == 3) {
            m_refreshDof = 0;
            m_staleNear[p] = 0;
            m_refreshPoint = k + 1;
        }
        --dofs;
    }
    m_timings.solveMs += msSince(started);
}

void CorotationalFem::markStaleNear(const std::vector<std::size_t>& removed) {
    const std::size_t n = m_x.size();
    m_staleNear.resize(n, 0);
    m_refreshDof = 0; // the point being refreshed, if near this cut too, starts over
    std::vector<char> touched(n, 0);
    for (const std::size_t t : removed)
        for (const std::int32_t p : m_tets[t])
            touched[static_cast<std::size_t>(p)] = 1;
    // The tets on those points (the incidence lists every tet of a point) bring their other points in.
    for (std::size_t p = 0; p < n; ++p) {
        if (!touched[p])
            continue;
        m_staleNear[p] = 1;
        for (std::size_t k = m_incidenceStart[p]; k < m_incidenceStart[p + 1]; ++k)
            for (const std::int32_t q : m_tets[m_incidence[k].first])
                m_staleNear[static_cast<std::size_t>(q)] = 1;
    }
}

void CorotationalFem::precomputeInto(Factor& f, const std::vector<std::int32_t>& list,
                                     const std::vector<std::array<bool, 3>>& fixed, WorkerTeam& team,
                                     std::vector<double>& compliance) {
    const std::size_t n = fixed.size();
    const std::size_t m3 = 3 * list.size();
    compliance.assign(m3 * m3, 0.0);
    std::vector<double> column(3 * n);
    for (std::size_t k = 0; k < list.size(); ++k)
        for (std::size_t d = 0; d < 3; ++d) {
            std::fill(column.begin(), column.end(), 0.0);
            column[3 * static_cast<std::size_t>(list[k]) + d] = 1.0;
            solveWith(f, fixed, team, column);
            for (std::size_t j = 0; j < list.size(); ++j)
                for (std::size_t e = 0; e < 3; ++e)
                    compliance[(3 * j + e) * m3 + 3 * k + d] = column[3 * static_cast<std::size_t>(list[j]) + e];
        }
    // And each of their dofs through L^-1 alone, so a row on them pairs with a row elsewhere at the cost of a sum.
    std::vector<int> dofs;
    for (std::size_t k = 0; k < list.size(); ++k)
        for (std::size_t d = 0; d < 3; ++d) {
            const std::size_t dof = 3 * static_cast<std::size_t>(list[k]) + d;
            if (!fixed[dof / 3][d])
                dofs.push_back(f.oldToNew[dof]);
        }
    f.computeColumns(dofs, team);
}

FemConstraint contactRow(const std::array<std::int32_t, 3>& points, const std::array<double, 3>& weights,
                         const Vec3& normal, const Vec3& planePointM) {
    FemConstraint row;
    row.offset = dot(normal, planePointM);
    for (std::size_t k = 0; k < 3; ++k) {
        if (weights[k] == 0.0)
            continue;
        row.points.push_back(points[k]);
        row.gradient.push_back(normal * -weights[k]);
    }
    return row;
}

double punchSubElementCompliance(double punchRadiusM, double edgeM, const std::array<double, 3>& weights,
                                 const FemMaterial& material) {
    const double nu = material.poissonRatio, e = material.youngsModulusPa;
    if (!(punchRadiusM > 0.0) || !(edgeM > 0.0) || !(e > 0.0) || !std::isfinite(nu) || !std::isfinite(edgeM))
        return 0.0;
    // alpha(nu): the punch's effective radius per element size for a load on one point (h = 6 mm).
    constexpr std::array<std::pair<double, double>, 3> kAlpha{{{0.45, 0.418}, {0.47, 0.430}, {0.49, 0.492}}};
    double alpha = kAlpha.front().second;
    if (nu >= kAlpha.back().first)
        alpha = kAlpha.back().second;
    else
        for (std::size_t i = 0; i + 1 < kAlpha.size(); ++i)
            if (nu >= kAlpha[i].first && nu <= kAlpha[i + 1].first) {
                const double s = (nu - kAlpha[i].first) / (kAlpha[i + 1].first - kAlpha[i].first);
                alpha = kAlpha[i].second + s * (kAlpha[i + 1].second - kAlpha[i].second);
            }
    double sum = 0.0, squares = 0.0;
    for (const double w : weights) {
        const double clamped = std::clamp(std::isfinite(w) ? w : 0.0, 0.0, 1.0);
        sum += clamped;
        squares += clamped * clamped;
    }
    const double s = sum > 0.0 ? squares / (sum * sum) : 1.0;
    constexpr double kPi = 3.14159265358979323846;
    const double scale = (1.0 - nu * nu) / e;
    const double mesh = scale / edgeM * (s / (2.0 * alpha) + (1.0 - s) / kPi);
    const double punch = scale / (2.0 * punchRadiusM);
    return std::max(0.0, punch - mesh);
}

double punchDimpleStiffening(double dimpleM, double punchRadiusM, const FemMaterial& material, double maxStiffening) {
    const double c = material.stiffeningStrain;
    if (!(c > 0.0) || !(punchRadiusM > 0.0) || !(dimpleM > 0.0) || !std::isfinite(dimpleM))
        return 1.0;
    const double x = std::min(std::sqrt(2.0 / 3.0) * dimpleM / punchRadiusM / c, 20.0);
    const double secant = x < 1e-4 ? 1.0 + x * x / 6.0 : std::sinh(x) / x;
    return std::clamp(secant, 1.0, std::max(1.0, maxStiffening));
}

namespace {

/// R^T v for a point's rotation R (row-major): a vector of the tissue's frame in the rest frame the factor has.
Vec3 toRestFrame(const std::array<double, 9>& r, const Vec3& v) {
    return {r[0] * v.x + r[3] * v.y + r[6] * v.z, r[1] * v.x + r[4] * v.y + r[7] * v.z,
            r[2] * v.x + r[5] * v.y + r[8] * v.z};
}

} // namespace

void CorotationalFem::forwardEntries(const std::vector<std::pair<std::int32_t, Vec3>>& forces,
                                     std::vector<std::pair<int, double>>& b) const {
    // b = P R^T f in the factor's order, the held dofs left out (the solves zero them).
    b.clear();
    const bool warped = m_pointR.size() == m_x.size();
    const Factor& f = *m_factor;
    for (const auto& [point, force] : forces) {
        const auto p = static_cast<std::size_t>(point);
        const Vec3 g = warped ? toRestFrame(m_pointR[p], force) : force;
        for (std::size_t d = 0; d < 3; ++d)
            if (!m_fixed[p][d] && g[static_cast<int>(d)] != 0.0)
                b.emplace_back(f.oldToNew[3 * p + d], g[static_cast<int>(d)]);
    }
}

void CorotationalFem::forwardRows(const std::vector<FemConstraint>& rows) const {
    const Factor& f = *m_factor;
    const std::size_t k = rows.size();
    f.rowY.resize(k);
    f.rowB.resize(k);
    std::vector<std::pair<std::int32_t, Vec3>> gradient;
    std::vector<int> dofs;
    for (std::size_t i = 0; i < k; ++i) {
        const FemConstraint& row = rows[i];
        gradient.clear();
        for (std::size_t a = 0; a < row.points.size(); ++a)
            gradient.emplace_back(row.points[a], row.gradient[a]);
        forwardEntries(gradient, f.rowB[i]);
        if (row.points.size() <= kColumnRowPoints)
            for (const auto& entry : f.rowB[i])
                dofs.push_back(entry.first);
    }
    // Each row a sum of its dofs' columns (those not computed for this factor yet are, once); a row on many points
    // one forward solve.
    f.computeColumns(dofs, *m_team);
    m_team->run(k, std::max<std::size_t>(1, (k + 1) / 2), [&](std::size_t chunk, std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i)
            if (rows[i].points.size() <= kColumnRowPoints)
                f.combine(f.rowB[i], chunk, f.rowY[i]);
            else
                f.forward(f.rowB[i], chunk, f.rowY[i]);
    });
}

void CorotationalFem::forwardForced() const {
    const Factor& f = *m_factor;
    std::vector<std::pair<std::int32_t, Vec3>> forces;
    for (const std::int32_t p : m_forcedPoints)
        forces.emplace_back(p, m_constraintForce[static_cast<std::size_t>(p)]);
    std::vector<std::pair<int, double>> b;
    forwardEntries(forces, b);
    if (forces.size() > kColumnCorrectionPoints) {
        f.forward(b, 0, f.forcedY);
        return;
    }
    std::vector<int> dofs;
    for (const auto& entry : b)
        dofs.push_back(entry.first);
    f.computeColumns(dofs, *m_team);
    f.combine(b, 0, f.forcedY);
}

bool CorotationalFem::correctByColumns(const std::vector<std::pair<std::int32_t, Vec3>>& change,
                                       const std::vector<FemConstraint>& rows, std::vector<Vec3>& x) const {
    // The points moved exactly: those the forces changed on and the rows' own (so every row holds at the step's end).
    std::vector<std::int32_t> exact;
    for (const auto& entry : change)
        exact.push_back(entry.first);
    for (const FemConstraint& row : rows) {
        if (row.points.size() > kColumnRowPoints)
            return false;
        exact.insert(exact.end(), row.points.begin(), row.points.end());
    }
    std::sort(exact.begin(), exact.end());
    exact.erase(std::unique(exact.begin(), exact.end()), exact.end());
    if (exact.size() > kColumnCorrectionPoints)
        return false;
    const Factor& f = *m_factor;
    // z = L^-1 P R^T df; a dof j's motion is then (R H^-1 R^T df)_j = R (y_j^T D^-1 z) with y_j its column.
    std::vector<std::pair<int, double>> b;
    forwardEntries(change, b);
    std::vector<int> dofs;
    for (const auto& entry : b)
        dofs.push_back(entry.first);
    for (const std::int32_t p : exact)
        for (std::size_t d = 0; d < 3; ++d)
            if (!m_fixed[static_cast<std::size_t>(p)][d])
                dofs.push_back(f.oldToNew[3 * static_cast<std::size_t>(p) + d]);
    f.computeColumns(dofs, *m_team);
    Factor::Sparse z;
    f.combine(b, 0, z);
    f.nextStamp(0);                           // sizes the scratch
    std::vector<double>& scaled = f.dense[0]; // zero between uses
    for (std::size_t t = 0; t < z.index.size(); ++t) {
        const auto j = static_cast<std::size_t>(z.index[t]);
        scaled[j] = z.value[t] / f.diag[j];
    }
    const bool warped = m_pointR.size() == m_x.size();
    std::vector<Vec3> moved(exact.size());
    for (std::size_t k = 0; k < exact.size(); ++k) {
        const auto p = static_cast<std::size_t>(exact[k]);
        Vec3 u{};
        for (std::size_t d = 0; d < 3; ++d) {
            if (m_fixed[p][d])
                continue;
            const Factor::Sparse& y = f.columnY[static_cast<std::size_t>(f.oldToNew[3 * p + d])];
            double sum = 0.0;
            for (std::size_t t = 0; t < y.index.size(); ++t)
                sum += y.value[t] * scaled[static_cast<std::size_t>(y.index[t])];
            u[static_cast<int>(d)] = sum;
        }
        if (warped) {
            const Mat3& r = m_pointR[p];
            u = {r[0] * u.x + r[1] * u.y + r[2] * u.z, r[3] * u.x + r[4] * u.y + r[5] * u.z,
                 r[6] * u.x + r[7] * u.y + r[8] * u.z};
        }
        moved[k] = u;
    }
    for (const int j : z.index)
        scaled[static_cast<std::size_t>(j)] = 0.0;
    // The rest of the precomputed surface through its block (the change's part on it), then the exact points.
    if (m_compliantCount > 0) {
        std::vector<Vec3> response;
        surfaceResponse(change, response);
        for (std::size_t k = 0; k < m_compliantCount; ++k)
            x[static_cast<std::size_t>(m_compliantList[k])] += response[k];
        for (std::size_t k = 0; k < exact.size(); ++k) {
            const std::int32_t index = m_compliantIndex[static_cast<std::size_t>(exact[k])];
            if (index >= 0)
                x[static_cast<std::size_t>(exact[k])] -= response[static_cast<std::size_t>(index)];
        }
    }
    for (std::size_t k = 0; k < exact.size(); ++k)
        x[static_cast<std::size_t>(exact[k])] += moved[k];
    return true;
}

void CorotationalFem::forwardProducts(std::vector<double>& out) const {
    // y_row^T D^-1 y_forced: each row's gradient times R H^-1 R^T f, over the two reaches' common columns.
    const Factor& f = *m_factor;
    f.nextStamp(0);                           // sizes the scratch
    std::vector<double>& scaled = f.dense[0]; // zero between uses
    for (std::size_t t = 0; t < f.forcedY.index.size(); ++t) {
        const auto j = static_cast<std::size_t>(f.forcedY.index[t]);
        scaled[j] = f.forcedY.value[t] / f.diag[j];
    }
    out.assign(f.rowY.size(), 0.0);
    for (std::size_t i = 0; i < f.rowY.size(); ++i) {
        double s = 0.0;
        for (std::size_t t = 0; t < f.rowY[i].index.size(); ++t)
            s += f.rowY[i].value[t] * scaled[static_cast<std::size_t>(f.rowY[i].index[t])];
        out[i] = s;
    }
    for (const int j : f.forcedY.index)
        scaled[static_cast<std::size_t>(j)] = 0.0;
}

void CorotationalFem::complianceBetween(const std::vector<FemConstraint>& rows, bool forwarded,
                                        std::vector<double>& w) {
    // Two rows of a few points on the precomputed surface: W_ij = sum g_ia^T R_a S_ab R_b^T g_jb from the block S.
    // A pair with a row elsewhere: W = G R H^-1 R^T G^T = Y^T D^-1 Y with Y = L^-1 P R^T G^T, each row's column of Y
    // a sum of its points' columns of L^-1 (forwardRows): the rows' own entries of H^-1 without a whole solve each.
    const std::size_t k = rows.size();
    w.assign(k * k, 0.0);
    std::vector<char> onBlock(k, 0);
    bool all = true;
    for (std::size_t i = 0; i < k; ++i) {
        bool on = m_compliantCount > 0 && rows[i].points.size() <= kColumnRowPoints;
        for (const std::int32_t p : rows[i].points)
            on = on && (precomputedAt(static_cast<std::size_t>(p)) || held(static_cast<std::size_t>(p)));
        onBlock[i] = on ? 1 : 0;
        all = all && on;
    }
    const std::size_t m3 = m_complianceStride;
    const bool warped = m_pointR.size() == m_x.size();
    const auto blockEntry = [&](std::size_t i, std::size_t j) {
        double s = 0.0;
        for (std::size_t a = 0; a < rows[i].points.size(); ++a) {
            const auto pa = static_cast<std::size_t>(rows[i].points[a]);
            if (m_compliantIndex[pa] < 0)
                continue; // a held point: it does not move
            const Vec3 ga = warped ? toRestFrame(m_pointR[pa], rows[i].gradient[a]) : rows[i].gradient[a];
            const std::size_t ra = 3 * static_cast<std::size_t>(m_compliantIndex[pa]);
            for (std::size_t b = 0; b < rows[j].points.size(); ++b) {
                const auto pb = static_cast<std::size_t>(rows[j].points[b]);
                if (m_compliantIndex[pb] < 0)
                    continue;
                const Vec3 gb = warped ? toRestFrame(m_pointR[pb], rows[j].gradient[b]) : rows[j].gradient[b];
                const std::size_t cb = 3 * static_cast<std::size_t>(m_compliantIndex[pb]);
                for (std::size_t r = 0; r < 3; ++r)
                    for (std::size_t c = 0; c < 3; ++c)
                        s += ga[static_cast<int>(r)] * m_compliance[(ra + r) * m3 + cb + c] * gb[static_cast<int>(c)];
            }
        }
        return s;
    };
    if (!all && !forwarded)
        forwardRows(rows);
    const Factor* f = all ? nullptr : m_factor.get();
    m_team->run(k, std::max<std::size_t>(1, (k + 1) / 2), [&](std::size_t chunk, std::size_t begin, std::size_t end) {
        std::vector<double>* scaled = nullptr; // zero between uses
        if (f) {
            f->nextStamp(chunk); // sizes the scratch
            scaled = &f->dense[chunk];
        }
        for (std::size_t i = begin; i < end; ++i) {
            const Factor::Sparse* yi = f ? &f->rowY[i] : nullptr;
            bool spread = false;
            for (std::size_t j = i; j < k; ++j) {
                double s = 0.0;
                if (onBlock[i] && onBlock[j]) {
                    s = blockEntry(i, j);
                } else {
                    if (!spread) {
                        for (std::size_t t = 0; t < yi->index.size(); ++t)
                            (*scaled)[static_cast<std::size_t>(yi->index[t])] =
                                yi->value[t] / f->diag[static_cast<std::size_t>(yi->index[t])];
                        spread = true;
                    }
                    const Factor::Sparse& yj = f->rowY[j];
                    for (std::size_t t = 0; t < yj.index.size(); ++t)
                        s += yj.value[t] * (*scaled)[static_cast<std::size_t>(yj.index[t])];
                }
                w[i * k + j] = s;
                w[j * k + i] = s;
            }
            if (spread)
                for (const int index : yi->index)
                    (*scaled)[static_cast<std::size_t>(index)] = 0.0;
        }
    });
}

bool CorotationalFem::onPrecomputedSurface(const std::vector<FemConstraint>& rows) const {
    if (m_compliantCount == 0)
        return false;
    for (const FemConstraint& row : rows)
        for (const std::int32_t p : row.points)
            if (!precomputedAt(static_cast<std::size_t>(p)) && !held(static_cast<std::size_t>(p)))
                return false;
    for (const std::int32_t p : m_forcedPoints)
        if (!precomputedAt(static_cast<std::size_t>(p)) && !held(static_cast<std::size_t>(p)))
            return false;
    return true;
}

bool CorotationalFem::held(std::size_t point) const {
    return m_fixed[point][0] && m_fixed[point][1] && m_fixed[point][2];
}

void CorotationalFem::surfaceResponse(const std::vector<std::pair<std::int32_t, Vec3>>& forces,
                                      std::vector<Vec3>& out) const {
    // out = R S R^T f on every precomputed point (the rest compliance warped by the points' rotations).
    const std::size_t m3 = 3 * m_compliantCount;
    out.assign(m_compliantCount, Vec3{});
    const bool warped = m_pointR.size() == m_x.size();
    std::vector<double> local(m3, 0.0);
    for (const auto& [p, f] : forces) {
        const auto pi = static_cast<std::size_t>(p);
        if (m_compliantIndex[pi] < 0)
            continue; // a held point: its force goes to the support
        Vec3 g = f;
        if (warped) {
            const Mat3& r = m_pointR[pi];
            g = {r[0] * f.x + r[3] * f.y + r[6] * f.z, r[1] * f.x + r[4] * f.y + r[7] * f.z,
                 r[2] * f.x + r[5] * f.y + r[8] * f.z};
        }
        const std::size_t c = 3 * static_cast<std::size_t>(m_compliantIndex[pi]);
        for (std::size_t row = 0; row < m3; ++row) {
            const double* s = &m_compliance[row * m_complianceStride + c];
            local[row] += s[0] * g.x + s[1] * g.y + s[2] * g.z;
        }
    }
    for (std::size_t k = 0; k < m_compliantCount; ++k) {
        const Vec3 u{local[3 * k], local[3 * k + 1], local[3 * k + 2]};
        out[k] = u;
        if (warped) {
            const Mat3& r = m_pointR[static_cast<std::size_t>(m_compliantList[k])];
            out[k] = {r[0] * u.x + r[1] * u.y + r[2] * u.z, r[3] * u.x + r[4] * u.y + r[5] * u.z,
                      r[6] * u.x + r[7] * u.y + r[8] * u.z};
        }
    }
}

void CorotationalFem::solveContacts(std::vector<FemConstraint>& rows, std::size_t external,
                                    const ObstacleCompliance& obstacle, const std::vector<double>& gap, bool forwarded,
                                    std::vector<double>& lambda) {
    const auto started = Clock::now();
    const std::size_t k = rows.size();
    std::vector<double> w;
    complianceBetween(rows, forwarded, w);
    // The caller's rows' own block is what the haptics renders between steps.
    m_lastW.assign(external * external, 0.0);
    for (std::size_t i = 0; i < external; ++i)
        for (std::size_t j = 0; j < external; ++j)
            m_lastW[i * external + j] = w[i * k + j];
    // The obstacles' compliance is between the caller's rows (the volume rows touch no obstacle).
    if (obstacle.matrix.size() == external * external)
        for (std::size_t i = 0; i < external; ++i)
            for (std::size_t j = 0; j < external; ++j) {
                const double o = obstacle.matrix[i * external + j];
                w[i * k + j] += std::isfinite(o) ? o : 0.0;
            }
    for (std::size_t i = 0; i < k; ++i)
        w[i * k + i] += std::max(0.0, rows[i].selfCompliance);
    lambda.assign(k, 0.0);
    solveComplementarity(w, gap, m_settings.maxConstraintForce, m_settings.contactSweeps, lambda);
    m_timings.contactsMs += msSince(started);
}

void CorotationalFem::volumeRows(const std::vector<Vec3>& x, std::vector<FemConstraint>& rows) const {
    const double bound = m_settings.minVolumeRatio;
    if (!(bound > 0.0))
        return;
    const double guard = bound + std::max(0.0, m_settings.volumeGuardBand);
    for (std::size_t t = 0; t < m_tets.size(); ++t) {
        if (m_removed[t])
            continue;
        const Tet& tet = m_tets[t];
        const auto p = [&tet](std::size_t k) { return static_cast<std::size_t>(tet[k]); };
        const Vec3 e1 = x[p(1)] - x[p(0)], e2 = x[p(2)] - x[p(0)], e3 = x[p(3)] - x[p(0)];
        const double ratio = dot(e1, cross(e2, e3)) / m_restDet[t];
        if (!(ratio < guard) || !std::isfinite(ratio))
            continue;
        // C = L (det / det0 - bound) >= 0, a length (L the tet's size), so its force is in newtons like a contact's.
        const double length = std::cbrt(m_volume[t]);
        const double scale = length / m_restDet[t];
        FemConstraint row;
        row.points = {tet[0], tet[1], tet[2], tet[3]};
        const Vec3 g1 = cross(e2, e3) * scale, g2 = cross(e3, e1) * scale, g3 = cross(e1, e2) * scale;
        row.gradient = {(g1 + g2 + g3) * -1.0, g1, g2, g3};
        double offset = length * (ratio - bound);
        for (std::size_t a = 0; a < 4; ++a)
            offset -= dot(row.gradient[a], x[p(a)]);
        row.offset = offset;
        rows.push_back(std::move(row));
    }
}

void solveComplementarity(const std::vector<double>& w, const std::vector<double>& gap, double maxForce, int sweeps,
                          std::vector<double>& lambda) {
    const std::size_t k = gap.size();
    if (w.size() != k * k || lambda.size() != k)
        return;
    for (int sweep = 0; sweep < sweeps; ++sweep) {
        double change = 0.0, largest = 0.0;
        for (std::size_t i = 0; i < k; ++i) {
            if (!(w[i * k + i] > 0.0))
                continue;
            double g = gap[i];
            for (std::size_t j = 0; j < k; ++j)
                g += w[i * k + j] * lambda[j];
            const double next = std::clamp(lambda[i] - g / w[i * k + i], 0.0, maxForce);
            change = std::max(change, std::abs(next - lambda[i]) * std::sqrt(w[i * k + i]));
            largest = std::max(largest, std::abs(next) * std::sqrt(w[i * k + i]));
            lambda[i] = next;
        }
        if (change <= 1e-10 * largest)
            break;
    }
}

void CorotationalFem::step(const std::vector<Vec3>& externalForcesN, std::vector<FemConstraint>& contacts,
                           const ObstacleCompliance& obstacle) {
    const std::size_t n = m_x.size();
    const double h = m_settings.stepS, alpha = m_settings.rayleighMassPerS;
    m_timings = {};
    refreshStaleSurface(m_settings.surfaceRefreshDofs);
    m_xStart = m_x;
    const std::vector<Vec3> vStart = m_v;
    // Valid rows only (a point out of range would corrupt memory: dropped).
    contacts.erase(std::remove_if(contacts.begin(), contacts.end(),
                                  [n](const FemConstraint& c) {
                                      if (c.points.size() != c.gradient.size() || !std::isfinite(c.offset) ||
                                          !std::isfinite(c.selfCompliance))
                                          return true;
                                      for (std::size_t a = 0; a < c.points.size(); ++a)
                                          if (c.points[a] < 0 || static_cast<std::size_t>(c.points[a]) >= n ||
                                              !isFinite(c.gradient[a]))
                                              return true;
                                      return false;
                                  }),
                   contacts.end());
    // The predictor x_n + h v_n, with the held degrees of freedom at their targets.
    std::vector<Vec3> x(n), v(n);
    for (std::size_t i = 0; i < n; ++i) {
        x[i] = m_x[i];
        for (int d = 0; d < 3; ++d)
            if (m_fixed[i][static_cast<std::size_t>(d)])
                x[i][d] = m_target[i][d];
    }
    std::vector<double> rhs(3 * n), lambda, gap;
    std::vector<FemConstraint> rows;
    m_lastVolumeRows = 0;
    // A tet held at the volume bound in the last iteration: the next chord step is checked by the line search.
    bool atBound = m_lastBoundRows > 0;
    m_lastBoundRows = 0;
    std::vector<std::pair<std::int32_t, Vec3>> change;
    std::vector<Vec3> response;
    std::vector<double> lastAlong; // off the surface: the last forces' motion along each row
    // The residual at positions y (into rhs as -r, free dofs), its norm.
    const auto residual = [&](const std::vector<Vec3>& y) {
        for (std::size_t i = 0; i < n; ++i)
            v[i] = (y[i] - m_xStart[i]) / h;
        internalForces(y, v, m_force);
        double sum2 = 0.0;
        for (std::size_t i = 0; i < n; ++i) {
            const Vec3 inertia =
                (y[i] - m_xStart[i] - vStart[i] * h) * (m_mass[i] / (h * h)) + v[i] * (alpha * m_mass[i]);
            const Vec3 tether = (y[i] - m_rest[i]) * m_tetherStiffness[i];
            const Vec3 f = i < externalForcesN.size() && isFinite(externalForcesN[i]) ? externalForcesN[i] : Vec3{};
            const Vec3 r = inertia + tether - m_force[i] - f - m_constraintForce[i];
            for (int d = 0; d < 3; ++d) {
                rhs[3 * i + static_cast<std::size_t>(d)] = -r[d];
                if (!m_fixed[i][static_cast<std::size_t>(d)])
                    sum2 += r[d] * r[d];
            }
        }
        return std::sqrt(sum2);
    };
    std::vector<Vec3> trial(n);
    std::vector<double> increment(3 * n);
    std::vector<double> negResidual; // -r(x) before the chord solve (the search at the bound's slope)
    for (int it = 0; it < m_settings.iterations; ++it) {
        const double before = residual(x);
        const bool boundSearch = !m_settings.lineSearch && m_settings.lineSearchAtVolumeBound && atBound;
        if (boundSearch)
            negResidual = rhs;
        solveWarped(rhs);
        increment = rhs;
        // The chord step is the rest matrix's: where the tissue has stiffened beyond twice that, or a tet is held at
        // its volume bound, it overshoots, so the step is shortened.
        const bool search = m_settings.lineSearch || boundSearch;
        m_timings.searchedIterations += search ? 1 : 0;
        // An unchecked step is taken whole: a length the search shortened is not carried into steps it does not check.
        double length = m_settings.lineSearch ? std::min(1.0, 2.0 * m_stepLength) : 1.0;
        const auto takeStep = [&] {
            for (std::size_t i = 0; i < n; ++i)
                trial[i] = x[i] + Vec3{increment[3 * i], increment[3 * i + 1], increment[3 * i + 2]} * length;
        };
        if (boundSearch) {
            // At the bound: the residual's slope along the step, r(x + a d) . d, at a = 0 (negative: the rest matrix
            // is positive definite) and at the whole step. Still negative there, the step is taken whole; positive,
            // it overshot the residual's zero along the line, and the step goes to where the secant between the two
            // puts it. One force evaluation, and it cannot stall: a backtracking search on the residual's norm found
            // no shorter step that lowered it with a tet squeezed to the bound (its forces leave the warped rest
            // matrix's line; the norm is no merit function there), froze the tissue with 0.25 N of imbalance in a
            // 1.35 N push, and paid 13 force evaluations a step (docs/simulator.md, "The chord step at the bound").
            const auto slope = [&](const std::vector<double>& negR) {
                double sum = 0.0;
                for (std::size_t i = 0; i < n; ++i)
                    for (std::size_t d = 0; d < 3; ++d)
                        if (!m_fixed[i][d])
                            sum -= negR[3 * i + d] * increment[3 * i + d];
                return sum;
            };
            const double atStart = slope(negResidual);
            takeStep();
            residual(trial);
            const double atEnd = slope(rhs);
            if (std::isfinite(atStart) && std::isfinite(atEnd) && atStart < 0.0 && atEnd > 0.0) {
                length = std::max(kMinBoundStepLength, atStart / (atStart - atEnd));
                takeStep();
            }
        } else {
            for (int tries = 0;; ++tries) {
                takeStep();
                if (!search || tries >= 12)
                    break;
                const double after = residual(trial);
                if (std::isfinite(after) && after <= before * (1.0 + 1e-9) + 1e-12)
                    break;
                length *= 0.5;
            }
        }
        m_stepLength = length;
        x = trial;
        // The caller's rows, then the volume rows of the tets near their bound after this free motion.
        rows.resize(contacts.size());
        std::copy(contacts.begin(), contacts.end(), rows.begin());
        volumeRows(x, rows);
        m_lastVolumeRows = rows.size() - contacts.size();
        if (rows.empty() && m_forcedPoints.empty())
            continue;
        // The constraints' forces lambda (total): the gaps after the free motion, less what the last forces did in it.
        const bool surface = onPrecomputedSurface(rows);
        if (surface) {
            change.clear();
            for (const std::int32_t p : m_forcedPoints)
                change.emplace_back(p, m_constraintForce[static_cast<std::size_t>(p)]);
            surfaceResponse(change, response);
        } else {
            // Off the precomputed surface (a volume row's interior points): each row's and the last forces' forward
            // solve on its reach; the last forces' motion along a row is their product (forwardProduct).
            const auto started = Clock::now();
            m_timings.forwardIterations += 1;
            forwardRows(rows);
            if (!m_forcedPoints.empty()) {
                forwardForced();
                forwardProducts(lastAlong);
            } else
                lastAlong.assign(rows.size(), 0.0);
            m_timings.contactsMs += msSince(started);
        }
        gap.assign(rows.size(), 0.0);
        for (std::size_t c = 0; c < rows.size(); ++c) {
            const FemConstraint& row = rows[c];
            double g = row.offset;
            for (std::size_t a = 0; a < row.points.size(); ++a) {
                const auto p = static_cast<std::size_t>(row.points[a]);
                Vec3 last{};
                if (surface && !m_forcedPoints.empty() && m_compliantIndex[p] >= 0)
                    last = response[static_cast<std::size_t>(m_compliantIndex[p])];
                g += dot(row.gradient[a], x[p] - last);
            }
            if (!surface)
                g -= lastAlong[c];
            gap[c] = g;
        }
        solveContacts(rows, contacts.size(), obstacle, gap, !surface, lambda);
        m_lastBoundRows = 0;
        for (std::size_t c = contacts.size(); c < rows.size(); ++c)
            m_lastBoundRows += lambda[c] > 0.0 ? 1 : 0;
        atBound = m_lastBoundRows > 0;
        // The correction: the new forces less the last, on the surface through the precomputed compliance (the
        // interior follows in the next step's free motion), or on every dof by a solve.
        std::vector<Vec3> next(n, Vec3{});
        std::vector<std::int32_t> nextPoints;
        for (std::size_t c = 0; c < rows.size(); ++c) {
            if (lambda[c] <= 0.0)
                continue;
            for (std::size_t a = 0; a < rows[c].points.size(); ++a) {
                const auto p = static_cast<std::size_t>(rows[c].points[a]);
                if (next[p] == Vec3{})
                    nextPoints.push_back(rows[c].points[a]);
                next[p] += rows[c].gradient[a] * lambda[c];
            }
        }
        change.clear();
        for (const std::int32_t p : nextPoints)
            change.emplace_back(p, next[static_cast<std::size_t>(p)] - m_constraintForce[static_cast<std::size_t>(p)]);
        for (const std::int32_t p : m_forcedPoints)
            if (next[static_cast<std::size_t>(p)] == Vec3{})
                change.emplace_back(p, m_constraintForce[static_cast<std::size_t>(p)] * -1.0);
        if (change.empty()) {
            // The contacts' forces did not change: nothing to correct.
        } else if (surface) {
            surfaceResponse(change, response);
            for (std::size_t k = 0; k < m_compliantCount; ++k)
                x[static_cast<std::size_t>(m_compliantList[k])] += response[k];
        } else if (const auto started = Clock::now();
                   !m_settings.wholeCorrection && correctByColumns(change, rows, x)) {
            // Off the precomputed surface: exact on the points the forces act on and the rows', through the block
            // on the rest of the surface; the interior follows in the next step's free motion. Counted with the
            // solves, as the whole solve it replaces was.
            m_timings.solveMs += msSince(started);
        } else {
            std::fill(rhs.begin(), rhs.end(), 0.0);
            for (const auto& [p, f] : change)
                for (int d = 0; d < 3; ++d)
                    rhs[3 * static_cast<std::size_t>(p) + static_cast<std::size_t>(d)] += f[d];
            solveWarped(rhs);
            for (std::size_t i = 0; i < n; ++i)
                x[i] += Vec3{rhs[3 * i], rhs[3 * i + 1], rhs[3 * i + 2]};
        }
        for (const std::int32_t p : m_forcedPoints)
            m_constraintForce[static_cast<std::size_t>(p)] = Vec3{};
        m_forcedPoints = nextPoints;
        for (const std::int32_t p : m_forcedPoints)
            m_constraintForce[static_cast<std::size_t>(p)] = next[static_cast<std::size_t>(p)];
    }
    for (std::size_t c = 0; c < contacts.size(); ++c)
        contacts[c].force = c < lambda.size() ? lambda[c] : 0.0;
    if (m_lastVolumeRows > 0 && m_compliantCount > 0 && m_volumeRowPointsAdded < m_settings.volumeRowSurfacePoints) {
        // The volume rows' points off the precomputed surface join it (their columns follow by the refresh), as many
        // as the setting leaves room for, row by row.
        std::vector<std::int32_t> join;
        for (std::size_t c = contacts.size(); c < rows.size(); ++c) {
            std::vector<std::int32_t> rowPoints;
            for (const std::int32_t p : rows[c].points)
                if (m_compliantIndex[static_cast<std::size_t>(p)] < 0 && !held(static_cast<std::size_t>(p)) &&
                    std::find(join.begin(), join.end(), p) == join.end())
                    rowPoints.push_back(p);
            if (m_volumeRowPointsAdded + join.size() + rowPoints.size() > m_settings.volumeRowSurfacePoints)
                break;
            join.insert(join.end(), rowPoints.begin(), rowPoints.end());
        }
        m_volumeRowPointsAdded += join.size();
        extendPrecomputedSurface(join);
    }
    bool finite = true;
    for (std::size_t i = 0; i < n && finite; ++i)
        finite = isFinite(x[i]);
    if (!finite) {
        // Never hand on a NaN: the step is undone and the tissue held where it was, at rest.
        ++m_recoveries;
        x = m_xStart;
        for (FemConstraint& c : contacts)
            c.force = 0.0;
        for (const std::int32_t p : m_forcedPoints)
            m_constraintForce[static_cast<std::size_t>(p)] = Vec3{};
        m_forcedPoints.clear();
    }
    for (std::size_t i = 0; i < n; ++i) {
        m_v[i] = finite ? (x[i] - m_xStart[i]) / h : Vec3{};
        m_x[i] = x[i];
    }
    if (!m_settings.endResidual)
        return;
    // The residual at the step's end: the supports' reactions and the imbalance of the free degrees of freedom.
    internalForces(m_x, m_v, m_force);
    double sum2 = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        const Vec3 inertia = (m_v[i] - vStart[i]) * (m_mass[i] / h) + m_v[i] * (alpha * m_mass[i]);
        const Vec3 tether = (m_x[i] - m_rest[i]) * m_tetherStiffness[i];
        const Vec3 f = i < externalForcesN.size() && isFinite(externalForcesN[i]) ? externalForcesN[i] : Vec3{};
        const Vec3 r = inertia + tether - m_force[i] - f - m_constraintForce[i];
        Vec3 reaction{};
        for (int d = 0; d < 3; ++d) {
            if (m_fixed[i][static_cast<std::size_t>(d)])
                reaction[d] = r[d];
            else
                sum2 += r[d] * r[d];
        }
        m_reaction[i] = reaction;
    }
    m_residualNorm = std::sqrt(sum2);
}

void CorotationalFem::updatePointMeasures() {
    const std::size_t n = m_x.size();
    m_mass.assign(n, 0.0);
    m_pointVolume.assign(n, 0.0);
    m_pointBulk.assign(n, 0.0);
    for (std::size_t t = 0; t < m_tets.size(); ++t) {
        if (m_removed[t])
            continue;
        for (const std::int32_t p : m_tets[t]) {
            const auto i = static_cast<std::size_t>(p);
            m_mass[i] += m_materials[t].densityKgPerM3 * m_volume[t] / 4.0;
            m_pointVolume[i] += m_volume[t] / 4.0;
            m_pointBulk[i] += (m_lambda[t] + 2.0 * m_mu[t] / 3.0) * m_volume[t] / 4.0;
        }
    }
    for (std::size_t i = 0; i < n; ++i) {
        if (m_pointVolume[i] > 0.0)
            m_pointBulk[i] /= m_pointVolume[i];
        if (!(m_mass[i] > 0.0))
            m_mass[i] = 1e-12; // a point of no tet: it keeps the matrix definite and never moves
    }
}

std::vector<std::vector<std::size_t>> CorotationalFem::loosePieces() const {
    // Breadth first from every live tet with a held or tethered point, through shared faces; what is not reached
    // falls into pieces the same way.
    const std::size_t count = m_tets.size();
    std::vector<char> reached(count, 0);
    std::vector<std::size_t> stack;
    for (std::size_t t = 0; t < count; ++t) {
        if (m_removed[t])
            continue;
        for (const std::int32_t p : m_tets[t]) {
            const auto i = static_cast<std::size_t>(p);
            if (m_fixed[i][0] || m_fixed[i][1] || m_fixed[i][2] || m_tetherStiffness[i] > 0.0) {
                reached[t] = 1;
                stack.push_back(t);
                break;
            }
        }
    }
    const auto spread = [&](std::vector<std::size_t>* piece) {
        while (!stack.empty()) {
            const std::size_t t = stack.back();
            stack.pop_back();
            if (piece)
                piece->push_back(t);
            for (const std::int32_t k : m_neighbours[t]) {
                if (k < 0)
                    continue;
                const auto u = static_cast<std::size_t>(k);
                if (!m_removed[u] && !reached[u]) {
                    reached[u] = 1;
                    stack.push_back(u);
                }
            }
        }
    };
    spread(nullptr);
    std::vector<std::vector<std::size_t>> pieces;
    for (std::size_t t = 0; t < count; ++t)
        if (!m_removed[t] && !reached[t]) {
            reached[t] = 1;
            stack.push_back(t);
            pieces.emplace_back();
            spread(&pieces.back());
            std::sort(pieces.back().begin(), pieces.back().end());
        }
    return pieces;
}

bool CorotationalFem::pointIsManifold(std::size_t point, std::vector<std::size_t>* keep) const {
    // The point's link: the faces opposite it in its live tets. The live tets meet the point as a manifold when
    // their link faces are joined through edges into one disk (one simple border cycle) or a whole sphere.
    std::vector<std::size_t> tets;
    std::vector<std::array<std::int32_t, 3>> link;
    for (std::size_t k = m_incidenceStart[point]; k < m_incidenceStart[point + 1]; ++k) {
        const auto [t, corner] = m_incidence[k];
        if (m_removed[t])
            continue;
        tets.push_back(t);
        const Tet& tet = m_tets[t];
        link.push_back({tet[static_cast<std::size_t>(kTetFacePoints[corner][0])],
                        tet[static_cast<std::size_t>(kTetFacePoints[corner][1])],
                        tet[static_cast<std::size_t>(kTetFacePoints[corner][2])]});
    }
    if (keep)
        keep->clear();
    const std::size_t m = link.size();
    if (m == 0)
        return true;
    // Link edges (sorted pair, triangle); triangles sharing an edge are one part.
    std::vector<std::pair<std::pair<std::int32_t, std::int32_t>, std::size_t>> edges;
    for (std::size_t i = 0; i < m; ++i)
        for (int e = 0; e < 3; ++e) {
            std::int32_t a = link[i][static_cast<std::size_t>(e)], b = link[i][static_cast<std::size_t>((e + 1) % 3)];
            if (a > b)
                std::swap(a, b);
            edges.push_back({{a, b}, i});
        }
    std::sort(edges.begin(), edges.end());
    std::vector<std::size_t> parent(m);
    for (std::size_t i = 0; i < m; ++i)
        parent[i] = i;
    const auto root = [&parent](std::size_t i) {
        while (parent[i] != i)
            i = parent[i] = parent[parent[i]];
        return i;
    };
    for (std::size_t i = 1; i < edges.size(); ++i)
        if (edges[i].first == edges[i - 1].first) {
            const std::size_t a = root(edges[i].second), b = root(edges[i - 1].second);
            if (a != b)
                parent[std::max(a, b)] = std::min(a, b);
        }
    // Per part: its border edges (an edge of one of its triangles only) must form one simple cycle, or none.
    // `cycle`: with every border point on two border edges but more than one cycle, the edges of the first.
    std::vector<std::pair<std::int32_t, std::int32_t>> cycle;
    const auto closesIntoDisk = [&](std::size_t part, std::int32_t* pinch) {
        cycle.clear();
        std::vector<std::pair<std::int32_t, std::int32_t>> border;
        for (std::size_t i = 0; i < edges.size();) {
            std::size_t j = i, inPart = 0;
            while (j < edges.size() && edges[j].first == edges[i].first) {
                if (root(edges[j].second) == part)
                    ++inPart;
                ++j;
            }
            if (inPart == 1)
                border.push_back(edges[i].first);
            i = j;
        }
        if (border.empty())
            return true;
        std::vector<std::pair<std::int32_t, std::size_t>> ends; // (point, border edge)
        for (std::size_t e = 0; e < border.size(); ++e) {
            ends.push_back({border[e].first, e});
            ends.push_back({border[e].second, e});
        }
        std::sort(ends.begin(), ends.end());
        for (std::size_t i = 0; i < ends.size(); i += 2)
            if (i + 1 >= ends.size() || ends[i + 1].first != ends[i].first ||
                (i + 2 < ends.size() && ends[i + 2].first == ends[i].first)) {
                // A border point of other than two border edges: the edge from the point to it is singular.
                if (pinch)
                    *pinch = ends[i].first;
                return false;
            }
        // Walk the cycle from the first edge: it must take every border edge.
        std::size_t walked = 1, edge = 0;
        std::int32_t at = border[0].second;
        cycle.push_back(border[0]);
        while (at != border[0].first) {
            const auto it = std::lower_bound(ends.begin(), ends.end(), std::make_pair(at, std::size_t{0}));
            const std::size_t next = it->second == edge ? (it + 1)->second : it->second;
            edge = next;
            cycle.push_back(border[edge]);
            at = border[edge].first == at ? border[edge].second : border[edge].first;
            if (++walked > border.size())
                return false;
        }
        return walked == border.size();
    };
    std::vector<std::size_t> parts;
    for (std::size_t i = 0; i < m; ++i)
        if (root(i) == i)
            parts.push_back(i);
    if (parts.size() == 1 && closesIntoDisk(parts[0], nullptr))
        return true;
    if (keep) {
        // The part of most volume (the first on a tie), if it closes into a disk.
        std::size_t best = parts[0];
        double bestVolume = -1.0;
        for (const std::size_t part : parts) {
            double volume = 0.0;
            for (std::size_t i = 0; i < m; ++i)
                if (root(i) == part)
                    volume += m_volume[tets[i]];
            if (volume > bestVolume) {
                bestVolume = volume;
                best = part;
            }
        }
        std::int32_t pinch = -1;
        const bool disk = closesIntoDisk(best, &pinch);
        // A singular edge from the point to `pinch`: its tets fall into fans joined through faces round the edge; the
        // fan of most volume stays (the next round looks at the point again).
        std::vector<char> drop(m, 0);
        if (!disk && pinch >= 0) {
            std::vector<std::size_t> fan;
            for (std::size_t i = 0; i < m; ++i)
                if (root(i) == best && std::find(link[i].begin(), link[i].end(), pinch) != link[i].end())
                    fan.push_back(i);
            std::vector<std::size_t> group(fan.size());
            for (std::size_t a = 0; a < fan.size(); ++a)
                group[a] = a;
            const auto top = [&group](std::size_t a) {
                while (group[a] != a)
                    a = group[a] = group[group[a]];
                return a;
            };
            for (std::size_t a = 0; a < fan.size(); ++a)
                for (std::size_t b = a + 1; b < fan.size(); ++b) {
                    std::size_t shared = 0; // points in common besides the pinch: one is an edge through it
                    for (const std::int32_t p : link[fan[a]])
                        if (p != pinch && std::find(link[fan[b]].begin(), link[fan[b]].end(), p) != link[fan[b]].end())
                            ++shared;
                    if (shared > 0) {
                        const std::size_t ra = top(a), rb = top(b);
                        if (ra != rb)
                            group[std::max(ra, rb)] = std::min(ra, rb);
                    }
                }
            std::vector<double> volume(fan.size(), 0.0);
            for (std::size_t a = 0; a < fan.size(); ++a)
                volume[top(a)] += m_volume[tets[fan[a]]];
            std::size_t largest = 0;
            for (std::size_t a = 0; a < fan.size(); ++a)
                if (top(a) == a && volume[a] > volume[largest])
                    largest = a;
            for (std::size_t a = 0; a < fan.size(); ++a)
                if (top(a) != largest)
                    drop[fan[a]] = 1;
        }
        if (!disk && pinch < 0 && !cycle.empty()) {
            // More than one border cycle (the live tets a ring round the point, its boundary two cones meeting at it):
            // the shortest chain of triangles, joined through edges, from the first cycle to another goes, which
            // joins the two cycles into one.
            std::sort(cycle.begin(), cycle.end());
            const auto edgeOf = [&link](std::size_t i, int e) {
                std::int32_t a = link[i][static_cast<std::size_t>(e)],
                             b = link[i][static_cast<std::size_t>((e + 1) % 3)];
                return a < b ? std::make_pair(a, b) : std::make_pair(b, a);
            };
            std::vector<int> kind(m, 0); // 1: on the first cycle, 2: on another border edge
            for (std::size_t k = 0; k < edges.size(); ++k) {
                const std::size_t i = edges[k].second;
                if (root(i) != best)
                    continue;
                const bool single =
                    (k == 0 || edges[k - 1].first != edges[k].first || root(edges[k - 1].second) != best) &&
                    (k + 1 == edges.size() || edges[k + 1].first != edges[k].first ||
                     root(edges[k + 1].second) != best);
                if (!single)
                    continue;
                const bool first = std::binary_search(cycle.begin(), cycle.end(), edges[k].first);
                kind[i] |= first ? 1 : 2;
            }
            std::vector<std::int64_t> from(m, -2);
            std::vector<std::size_t> queue;
            for (std::size_t i = 0; i < m; ++i)
                if (root(i) == best && (kind[i] & 1)) {
                    from[i] = -1;
                    queue.push_back(i);
                }
            for (std::size_t q = 0; q < queue.size(); ++q) {
                const std::size_t i = queue[q];
                if (kind[i] & 2) {
                    for (std::int64_t k = static_cast<std::int64_t>(i); k >= 0; k = from[static_cast<std::size_t>(k)])
                        drop[static_cast<std::size_t>(k)] = 1;
                    break;
                }
                for (int e = 0; e < 3; ++e) {
                    const auto key = edgeOf(i, e);
                    for (auto it = std::lower_bound(edges.begin(), edges.end(), std::make_pair(key, std::size_t{0}));
                         it != edges.end() && it->first == key; ++it)
                        if (it->second != i && root(it->second) == best && from[it->second] == -2) {
                            from[it->second] = static_cast<std::int64_t>(i);
                            queue.push_back(it->second);
                        }
                }
            }
        }
        if (disk || pinch >= 0 || std::find(drop.begin(), drop.end(), 1) != drop.end())
            for (std::size_t i = 0; i < m; ++i)
                if (root(i) == best && !drop[i])
                    keep->push_back(tets[i]);
    }
    return false;
}

CorotationalFem::Removal CorotationalFem::removeTets(const std::vector<std::size_t>& tets, Refactor refactorMode) {
    Removal out;
    std::vector<std::int32_t> touched;
    std::vector<std::size_t> exposed; // live tets across a face of a removed one
    const auto take = [&](std::size_t t) {
        m_removed[t] = 1;
        out.removed.push_back(t);
        touched.insert(touched.end(), m_tets[t].begin(), m_tets[t].end());
        for (const std::int32_t u : m_neighbours[t])
            if (u >= 0 && !m_removed[static_cast<std::size_t>(u)])
                exposed.push_back(static_cast<std::size_t>(u));
    };
    for (const std::size_t t : tets)
        if (t < m_removed.size() && !m_removed[t])
            take(t);
    if (out.removed.empty())
        return out;
    // Chips, then the points the removal touched, until neither takes a tet (each round takes at least one).
    std::vector<std::size_t> keep;
    while (!touched.empty()) {
        for (std::vector<std::size_t>& piece : loosePieces()) {
            for (const std::size_t t : piece)
                take(t);
            out.chips.push_back(std::move(piece));
        }
        std::sort(touched.begin(), touched.end());
        touched.erase(std::unique(touched.begin(), touched.end()), touched.end());
        std::vector<std::int32_t> points;
        points.swap(touched);
        for (const std::int32_t p : points) {
            const auto i = static_cast<std::size_t>(p);
            if (pointIsManifold(i, &keep))
                continue;
            std::sort(keep.begin(), keep.end());
            for (std::size_t k = m_incidenceStart[i]; k < m_incidenceStart[i + 1]; ++k) {
                const std::size_t t = m_incidence[k].first;
                if (!m_removed[t] && !std::binary_search(keep.begin(), keep.end(), t)) {
                    take(t);
                    ++out.manifoldTets;
                }
            }
        }
        // Dangling tets: a tet the cut left held by one face or none (its other faces open to the fluid or the
        // outside) is a sliver of the mesh's resolution that no loop leaves in tissue; it goes with the cut.
        std::vector<std::size_t> candidates;
        candidates.swap(exposed);
        std::sort(candidates.begin(), candidates.end());
        candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
        for (const std::size_t t : candidates) {
            if (m_removed[t])
                continue;
            int held = 0;
            for (const std::int32_t u : m_neighbours[t])
                held += u >= 0 && !m_removed[static_cast<std::size_t>(u)] ? 1 : 0;
            if (held <= 1) {
                take(t);
                ++out.danglingTets;
            }
        }
    }
    std::sort(out.removed.begin(), out.removed.end());
    std::sort(out.chips.begin(), out.chips.end());
    m_liveTets -= out.removed.size();
    // Points of no live tet are held where they are.
    std::vector<char> live(m_x.size(), 0);
    for (std::size_t t = 0; t < m_tets.size(); ++t)
        if (!m_removed[t])
            for (const std::int32_t p : m_tets[t])
                live[static_cast<std::size_t>(p)] = 1;
    for (std::size_t i = 0; i < m_x.size(); ++i)
        if (!live[i] && !(m_fixed[i][0] && m_fixed[i][1] && m_fixed[i][2])) {
            m_fixed[i] = {true, true, true};
            m_target[i] = m_x[i];
            m_v[i] = Vec3{};
        }
    updatePointMeasures();
    m_factorStale = true;
    if (refactorMode == Refactor::Downdate) {
        // A rebuild running meanwhile works on its own copy; it is dropped when it ends (finishRefactor).
        bool exact = !(m_settings.nodalPressure && m_settings.nodalPressureMatrix);
        // A tet whose points all lost their last live tet (inside a chip) couples only points now held, which no
        // live point's row or column of the factor reaches once the tets between them and live points are out: its
        // stiffness can stay in the factor without changing a solve on the live points (the held ones are zero).
        for (const std::size_t t : out.removed) {
            const Tet& tet = m_tets[t];
            if (!live[static_cast<std::size_t>(tet[0])] && !live[static_cast<std::size_t>(tet[1])] &&
                !live[static_cast<std::size_t>(tet[2])] && !live[static_cast<std::size_t>(tet[3])])
                continue;
            if (!exact)
                break;
            exact = downdateTet(t);
            out.downdated += exact ? 1 : 0;
        }
        if (exact) {
            // The surface's precomputed compliance was the old factor's: kept, stale, for rows away from the cut;
            // its columns of L^-1 are the old factor's and go.
            m_complianceStale = m_compliantCount > 0;
            markStaleNear(out.removed);
            m_factor->dropColumns();
            m_factorPointVolume = m_pointVolume;
            m_factorStale = false;
        } else {
            out.downdated = 0; // the factor is rebuilt from the live tets instead
            refactorMode = Refactor::Now;
        }
    }
    if (refactorMode == Refactor::Now)
        refactor();
    return out;
}

bool CorotationalFem::startRefactor() {
    if (m_rebuild || !m_factor)
        return false;
    auto r = std::make_unique<Rebuild>();
    r->settings = m_settings;
    r->rest = m_rest;
    r->tets = m_tets;
    r->dmInv = m_dmInv;
    r->volume = m_volume;
    r->mu = m_mu;
    r->lambda = m_lambda;
    r->removed = m_removed;
    r->fixed = m_fixed;
    r->mass = m_mass;
    r->pointVolume = m_pointVolume;
    r->pointBulk = m_pointBulk;
    r->matrixStiffening = m_matrixStiffening;
    r->tetherStiffness = m_tetherStiffness;
    r->partition = m_partition;
    if (!m_compliantList.empty()) // the surface precomputed before (a downdate may have dropped it since)
        r->list = m_compliantList;
    r->liveTets = m_liveTets;
    Rebuild* job = r.get();
    r->thread = std::thread([job] { job->run(); });
    m_rebuild = std::move(r);
    return true;
}

bool CorotationalFem::finishRefactor() {
    if (!m_rebuild)
        return false;
    m_rebuild->thread.join();
    if (m_rebuild->liveTets != m_liveTets && !m_factorStale) {
        // Cuts since the start were downdated into the factor in use: it is the newer one.
        m_rebuild.reset();
        return false;
    }
    m_factor = std::move(m_rebuild->factor);
    if (!m_rebuild->list.empty()) {
        // The surface as precomputed with it (a downdate since the start had dropped the old one's).
        m_compliance = std::move(m_rebuild->compliance);
        m_compliantIndex.assign(m_x.size(), -1);
        for (std::size_t k = 0; k < m_rebuild->list.size(); ++k)
            m_compliantIndex[static_cast<std::size_t>(m_rebuild->list[k])] = static_cast<std::int32_t>(k);
        m_compliantCount = m_rebuild->list.size();
        m_compliantList = m_rebuild->list;
        m_complianceStride = 3 * m_compliantCount;
        // Stale when tets went since the start without a downdate (Refactor::Later): those points then solve.
        m_complianceStale = m_rebuild->liveTets != m_liveTets;
        m_staleNear.assign(m_x.size(), 0);
        if (m_complianceStale) {
            std::vector<std::size_t> since;
            for (std::size_t t = 0; t < m_tets.size(); ++t)
                if (m_removed[t] && !m_rebuild->removed[t])
                    since.push_back(t);
            markStaleNear(since);
        }
    }
    m_factorStale = m_rebuild->liveTets != m_liveTets;
    m_factorPointVolume = std::move(m_rebuild->pointVolume);
    m_factorFixed = std::move(m_rebuild->fixed);
    m_rebuild.reset();
    return true;
}

double CorotationalFem::factorStaleness() const {
    double stale = 0.0;
    for (std::size_t i = 0; i < m_pointVolume.size() && i < m_factorPointVolume.size(); ++i)
        if (m_pointVolume[i] > 0.0 && m_factorPointVolume[i] > 0.0)
            stale = std::max(stale, 1.0 - m_pointVolume[i] / m_factorPointVolume[i]);
    return stale;
}

void CorotationalFem::refactor() {
    m_rebuild.reset(); // a rebuild begun before would bring back an older factor
    assembleAndFactor();
    if (!m_compliantList.empty()) {
        const std::vector<std::int32_t> points = m_compliantList;
        const std::size_t added = m_volumeRowPointsAdded; // the same surface, with the points volume rows brought
        precomputeCompliance(points);
        m_volumeRowPointsAdded = added;
    }
    m_factorStale = false;
}

bool CorotationalFem::downdateTet(std::size_t t) {
    // The tet's block of the matrix as buildFactor assembles it (per-tet pressure), on the dofs free in the factor.
    Factor& f = *m_factor;
    const double stiffnessScale = 1.0 + m_settings.rayleighStiffnessS / m_settings.stepS;
    const std::array<Vec3, 4> g = shapeGradients(m_dmInv[t]);
    const double bulk = m_lambda[t] + 2.0 * m_mu[t] / 3.0;
    const double v = m_volume[t] * stiffnessScale;
    const double mu = m_mu[t] * (m_matrixStiffening.empty() ? 1.0 : m_matrixStiffening[t]);
    const double la = -2.0 * mu / 3.0 + bulk;
    const Tet& tet = m_tets[t];
    const auto held = [&](std::size_t corner, int axis) {
        return m_factorFixed[static_cast<std::size_t>(tet[corner])][static_cast<std::size_t>(axis)];
    };
    Eigen::Matrix<double, 12, 12> k = Eigen::Matrix<double, 12, 12>::Zero();
    for (std::size_t a = 0; a < 4; ++a)
        for (std::size_t b = 0; b < 4; ++b) {
            const double gg = dot(g[a], g[b]);
            for (int i = 0; i < 3; ++i)
                for (int j = 0; j < 3; ++j)
                    if (!held(a, i) && !held(b, j))
                        k(static_cast<Eigen::Index>(3 * a) + i, static_cast<Eigen::Index>(3 * b) + j) =
                            v * (la * g[a][i] * g[b][j] + mu * g[a][j] * g[b][i] + (i == j ? mu * gg : 0.0));
        }
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 12, 12>> eigen(k);
    const double top = eigen.eigenvalues().maxCoeff();
    std::vector<int> reach;
    for (Eigen::Index e = 0; e < 12; ++e) {
        const double lambda = eigen.eigenvalues()[e];
        if (!(lambda > 1e-12 * top))
            continue; // the rigid motions
        // L D L^T - w w^T, w = sqrt(lambda) times the eigenvector, by Gill, Golub, Murray & Saunders' method C1 on
        // the columns of w's reach (its entries' paths to the root), ascending.
        const std::uint32_t now = f.nextStamp(0);
        std::vector<double>& w = f.dense[0];
        std::vector<std::uint32_t>& marks = f.mark[0];
        reach.clear();
        for (Eigen::Index r = 0; r < 12; ++r) {
            const std::size_t corner = static_cast<std::size_t>(r) / 3;
            const int axis = static_cast<int>(r % 3);
            if (held(corner, axis))
                continue;
            int j = f.oldToNew[3 * static_cast<std::size_t>(tet[corner]) + static_cast<std::size_t>(axis)];
            w[static_cast<std::size_t>(j)] += std::sqrt(lambda) * eigen.eigenvectors()(r, e);
            for (; j >= 0 && marks[static_cast<std::size_t>(j)] != now; j = f.parent[static_cast<std::size_t>(j)]) {
                marks[static_cast<std::size_t>(j)] = now;
                reach.push_back(j);
            }
        }
        std::sort(reach.begin(), reach.end());
        double alpha = -1.0;
        bool ok = true;
        for (const int column : reach) {
            const auto j = static_cast<std::size_t>(column);
            const double p = w[j];
            if (p == 0.0)
                continue;
            const double dj = f.diag[j], dNew = dj + alpha * p * p;
            if (!(dNew > 1e-12 * dj) || !std::isfinite(dNew)) {
                ok = false;
                break;
            }
            const double beta = p * alpha / dNew;
            alpha *= dj / dNew;
            f.diag[j] = dNew;
            for (int q = f.colStart[j]; q < f.colStart[j + 1]; ++q) {
                const auto r = static_cast<std::size_t>(f.row[static_cast<std::size_t>(q)]);
                w[r] -= p * f.value[static_cast<std::size_t>(q)];
                f.value[static_cast<std::size_t>(q)] += beta * w[r];
            }
        }
        for (const int column : reach)
            w[static_cast<std::size_t>(column)] = 0.0;
        if (!ok)
            return false;
    }
    return true;
}

std::vector<std::int32_t> CorotationalFem::singularPoints() const {
    std::vector<std::int32_t> out;
    for (std::size_t i = 0; i < m_x.size(); ++i)
        if (!pointIsManifold(i, nullptr))
            out.push_back(static_cast<std::int32_t>(i));
    return out;
}

std::size_t CorotationalFem::looseLivePieces() const {
    return loosePieces().size();
}

double CorotationalFem::loadCompliance(const std::vector<Vec3>& forces) const {
    std::vector<double> u(3 * m_x.size(), 0.0);
    for (std::size_t i = 0; i < std::min(forces.size(), m_x.size()); ++i)
        for (int d = 0; d < 3; ++d)
            u[3 * i + static_cast<std::size_t>(d)] = isFinite(forces[i]) ? forces[i][d] : 0.0;
    std::vector<double> f = u;
    solveWarped(u);
    double s = 0.0;
    for (std::size_t k = 0; k < u.size(); ++k)
        s += f[k] * u[k];
    return s;
}

std::size_t CorotationalFem::factorNonZeros() const {
    return m_factor ? m_factor->row.size() + m_factor->diag.size() : 0;
}

Vec3 CorotationalFem::reactionN(std::size_t point) const {
    return point < m_reaction.size() ? m_reaction[point] : Vec3{};
}

double CorotationalFem::stiffeningArgument(std::size_t tet, const std::array<double, 9>& s) const {
    const double c = m_materials[tet].stiffeningStrain;
    if (!(c > 0.0))
        return 0.0;
    return std::min(std::sqrt(deviatoricNorm2(s)) / c, 20.0);
}

std::array<double, 9> CorotationalFem::corotatedStretch(std::size_t t, int iterations) const {
    const Tet& tet = m_tets[t];
    const auto p = [&tet](std::size_t k) { return static_cast<std::size_t>(tet[k]); };
    const Mat3 f = multiply(shapeMatrix(m_x[p(0)], m_x[p(1)], m_x[p(2)], m_x[p(3)]), m_dmInv[t]);
    std::array<double, 4> q = m_rotation[t];
    return multiplyTransposed(rotationOf(f, q, iterations), f);
}

double CorotationalFem::refactorStiffened() {
    // Each tet's tangent stiffening cosh(x) at the current shape: the chord iteration then converges as at rest.
    m_matrixStiffening.assign(m_tets.size(), 1.0);
    double largest = 1.0;
    for (std::size_t t = 0; t < m_tets.size(); ++t) {
        if (m_removed[t])
            continue;
        m_matrixStiffening[t] = std::cosh(stiffeningArgument(t, corotatedStretch(t, 4)));
        largest = std::max(largest, m_matrixStiffening[t]);
    }
    assembleAndFactor();
    return largest;
}

double CorotationalFem::stiffening(std::size_t tet, const std::array<double, 9>& s) const {
    if (!(m_materials[tet].stiffeningStrain > 0.0))
        return 1.0;
    const double x = stiffeningArgument(tet, s);
    return std::min(x < 1e-4 ? 1.0 + x * x / 6.0 : std::sinh(x) / x, m_settings.maxStiffening);
}

double CorotationalFem::stiffeningAt(std::size_t tet) const {
    if (tet >= m_tets.size() || m_removed[tet])
        return 1.0;
    return stiffening(tet, corotatedStretch(tet, 4));
}

double CorotationalFem::elasticEnergyJ() const {
    // mu |dev e|^2 per tet plus kappa / 2 theta^2, per tet or per point (nodal pressure).
    // The stiffening's energy 2 mu c^2 (cosh x - 1), x = |dev e| / c, up to the x* where its secant factor sinh x / x
    // reaches maxStiffening; beyond, the stress grows linearly with that factor, and so does the energy's rate.
    const double cap = m_settings.maxStiffening;
    double capX = 20.0;
    if (cap > 1.0 && std::sinh(20.0) / 20.0 > cap) {
        double lo = 1e-6, hi = 20.0;
        for (int i = 0; i < 100; ++i) {
            const double mid = 0.5 * (lo + hi);
            (std::sinh(mid) / mid < cap ? lo : hi) = mid;
        }
        capX = lo;
    }
    double energy = 0.0;
    std::vector<double> pointTheta(m_x.size(), 0.0);
    for (std::size_t t = 0; t < m_tets.size(); ++t) {
        if (m_removed[t])
            continue;
        const Tet& tet = m_tets[t];
        const auto p = [&tet](std::size_t k) { return static_cast<std::size_t>(tet[k]); };
        const Mat3 s = corotatedStretch(t, 8);
        const double theta = s[0] + s[4] + s[8] - 3.0;
        const double dev2 = deviatoricNorm2(s);
        const double c = m_materials[t].stiffeningStrain;
        const double x = c > 0.0 ? std::sqrt(dev2) / c : 0.0;
        const double stiffening =
            x <= capX ? 2.0 * m_mu[t] * c * c * (std::cosh(x) - 1.0)
                      : 2.0 * m_mu[t] * c * c * (std::cosh(capX) - 1.0) + m_mu[t] * cap * c * c * (x * x - capX * capX);
        energy += (c > 0.0 ? stiffening : m_mu[t] * dev2) * m_volume[t];
        const double tetShare = m_settings.nodalPressure ? m_settings.tetPressureShare : 1.0;
        if (m_settings.nodalPressure)
            for (std::size_t k = 0; k < 4; ++k)
                pointTheta[p(k)] += m_volume[t] / (4.0 * m_pointVolume[p(k)]) * theta;
        energy += tetShare * 0.5 * (m_lambda[t] + 2.0 * m_mu[t] / 3.0) * theta * theta * m_volume[t];
    }
    if (m_settings.nodalPressure)
        for (std::size_t i = 0; i < m_x.size(); ++i)
            energy += (1.0 - m_settings.tetPressureShare) * 0.5 * m_pointBulk[i] * pointTheta[i] * pointTheta[i] *
                      m_pointVolume[i];
    return energy;
}

double CorotationalFem::minVolumeRatio(std::size_t& inverted) const {
    inverted = 0;
    double smallest = 1e300;
    for (std::size_t t = 0; t < m_tets.size(); ++t) {
        if (m_removed[t])
            continue;
        const Tet& tet = m_tets[t];
        const auto p = [&tet](std::size_t k) { return static_cast<std::size_t>(tet[k]); };
        const double j = determinant(multiply(shapeMatrix(m_x[p(0)], m_x[p(1)], m_x[p(2)], m_x[p(3)]), m_dmInv[t]));
        if (j <= 0.0)
            ++inverted;
        smallest = std::min(smallest, j);
    }
    return smallest > 1e299 ? 1.0 : smallest;
}

double CorotationalFem::maxSpeedMPerS() const {
    double fastest = 0.0;
    for (const Vec3& v : m_v)
        fastest = std::max(fastest, norm(v));
    return fastest;
}

double CorotationalFem::kineticEnergyJ() const {
    double e = 0.0;
    for (std::size_t i = 0; i < m_v.size(); ++i)
        e += 0.5 * m_mass[i] * norm2(m_v[i]);
    return e;
}

} // namespace hs::mechanics
