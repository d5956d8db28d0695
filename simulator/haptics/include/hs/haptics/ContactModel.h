#pragma once
/// The haptics loop's local force model: the last physics step's contact problem re-solved at 1 kHz with the
/// device's new pose (sim::solveHapticContacts on the newest HapticFrame), as SOFA's LCPForceFeedback does (Saupin,
/// Duriez & Cotin 2008). The device gets the virtual coupling's force (Colgate, Stanley & Brown 1995): the tissue's
/// reaction with the solver's own compliance, so force is continuous between physics steps and at rest equals the
/// force the solver computed. A little damping along the generalized velocity while in contact keeps the loop passive
/// (Colgate & Schenkel, "Passivity of a class of sampled-data systems", 1997). No wall force once the frame says
/// perforated; a malformed frame gives no force.
///
/// Not thread-safe: one model per haptics loop. No allocation per tick once warmed up.

#include "hs/core/Vec3.h"
#include "hs/haptics/HapticDevice.h"
#include "hs/sim/Device.h"
#include "hs/sim/HapticFrame.h"

#include <array>
#include <cstddef>
#include <vector>

namespace hs::haptics {

struct ContactParams {
    double dampingNsPerMm = 0.001; ///< N*s/mm along the shaft while in contact (and N*mm*s/rad per mm^2 of lever)
    double velocityFilter = 0.2;   ///< 0..1, weight of the newest dof velocity in its low-pass estimate
};

struct ContactState {
    bool touching = false;
    std::size_t contacts = 0;   ///< the frame's contacts
    std::size_t pressing = 0;   ///< of them, those with a force this tick
    double largestForceN = 0.0; ///< the largest contact force this tick
};

class ContactModel {
public:
    explicit ContactModel(ContactParams params = {});
    /// The force for `sample` against `frame`; `dtS` the time since the previous update (for the velocity).
    /// The command is enabled with every value finite (not yet clamped to a device).
    ForceCommand update(const sim::HapticFrame& frame, const sim::DeviceSample& sample, double dtS);
    /// Forgets the velocity estimate.
    void reset();
    const ContactState& state() const { return m_state; }

private:
    ContactParams m_params;
    ContactState m_state;
    bool m_hasPrevious = false;
    std::array<double, 3> m_previous{};
    std::array<double, 3> m_velocity{};
    std::vector<double> m_forces;
};

} // namespace hs::haptics
