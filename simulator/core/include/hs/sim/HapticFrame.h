#pragma once
/// What the physics hands to the haptics loop after each step: a local linear model of the step's contacts, so the
/// 1 kHz loop renders the tissue's force between physics steps (docs/simulator.md, "Haptics"). The model is the one
/// the solver itself used: each contact's gap and how it changes with the scope's degrees of freedom, the tissue's
/// compliance between the contacts (W = J H^-1 J^T of the solver's matrix), the forces the step ended with, and the
/// virtual coupling's stiffness. The haptics loop re-solves that small complementarity problem with each new device
/// pose, as SOFA's LCPForceFeedback re-solves the last step's constraint problem (Saupin, Duriez & Cotin 2008), and
/// sends the device the coupling's force. Frames are immutable once published (std::shared_ptr<const HapticFrame>).
///
/// Scope degrees of freedom here, in SI: insertion (m), pitch and yaw about the pivot (rad).

#include "hs/core/Vec3.h"
#include "hs/sim/Scope.h"

#include <array>
#include <cstdint>
#include <vector>

namespace hs::sim {

/// A contact of the scope with the tissue as the step left it.
struct HapticContact {
    double gapM = 0.0;                     ///< m, at the end of the step (0 where the scope presses the wall)
    std::array<double, 3> scopeGradient{}; ///< the gap's change per scope dof: m/m, m/rad, m/rad
    double forceN = 0.0;                   ///< N, the tissue's force on the scope along `normal`
    Vec3 normal;                           ///< unit, from the tissue to the scope
    bool tip = false;                      ///< at the scope's tip (else on its shaft)
};

struct HapticFrame {
    std::uint64_t step = 0; ///< the physics step that produced it
    double timeS = 0.0;     ///< s, simulated time at that step
    ScopeFrame pivot;       ///< the cervical pivot and its axes
    ScopeConfig scope;      ///< the scope in use
    /// The physics' scope at the end of the step (insertion m, pitch rad, yaw rad): where the coupling holds it.
    std::array<double, 3> scopeDofs{};
    /// The virtual coupling between the device and the physics' scope: N/m, N m/rad, N m/rad.
    std::array<double, 3> couplingStiffness{1000.0, 3.6, 3.6};
    std::vector<HapticContact> contacts;
    /// The tissue's compliance between the contacts, m/N, row-major contacts.size() squared.
    std::vector<double> compliance;
    /// m/N: the tip's sub-element give, in series with every tip contact along their normals (n_i . n_j).
    double tipComplianceMPerN = 0.0;
    bool perforated = false; ///< the tip has gone through the wall: no wall force at the tip
};

/// The scope's degrees of freedom (SI) of a device sample.
inline std::array<double, 3> scopeDofsOf(const DeviceSample& sample) {
    constexpr double kRadPerDeg = 3.14159265358979323846 / 180.0;
    return {sample.insertionMm * 1e-3, sample.pitchDeg * kRadPerDeg, sample.yawDeg * kRadPerDeg};
}

/// The contacts' forces for the device pose `device` (SI dofs): the frame's complementarity problem re-solved
/// (projected Gauss-Seidel), and the coupling's generalized force on the device (N, N m, N m; it pulls the device
/// towards the physics' scope). Returns false for a malformed frame (sizes that disagree, values not finite).
bool solveHapticContacts(const HapticFrame& frame, const std::array<double, 3>& device, std::vector<double>& forcesN,
                         std::array<double, 3>& generalizedForce);

} // namespace hs::sim
