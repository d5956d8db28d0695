// The local contact model of the haptics loop (ContactModel.h).
#include "hs/haptics/ContactModel.h"

#include <algorithm>
#include <cmath>

namespace hs::haptics {

ContactModel::ContactModel(ContactParams params) : m_params(params) {
    m_forces.reserve(64);
}

void ContactModel::reset() {
    m_hasPrevious = false;
    m_state = {};
    m_velocity = {};
}

ForceCommand ContactModel::update(const sim::HapticFrame& frame, const sim::DeviceSample& sample, double dtS) {
    const std::array<double, 3> q = sim::scopeDofsOf(sample);
    if (m_hasPrevious && dtS > 0.0)
        for (std::size_t d = 0; d < 3; ++d)
            m_velocity[d] += ((q[d] - m_previous[d]) / dtS - m_velocity[d]) * m_params.velocityFilter;
    m_previous = q;
    m_hasPrevious = true;
    m_state = {};
    ForceCommand command;
    command.enabled = true;
    std::array<double, 3> generalized{0.0, 0.0, 0.0};
    if (frame.perforated || !sim::solveHapticContacts(frame, q, m_forces, generalized))
        return command; // no wall, or a frame that cannot be trusted: no force
    m_state.contacts = frame.contacts.size();
    Vec3 tip{};
    for (std::size_t i = 0; i < m_forces.size(); ++i) {
        if (m_forces[i] <= 0.0)
            continue;
        ++m_state.pressing;
        m_state.largestForceN = std::max(m_state.largestForceN, m_forces[i]);
        tip += frame.contacts[i].normal * m_forces[i];
    }
    m_state.touching = m_state.pressing > 0;
    if (m_state.touching) {
        // Damping resists the device's motion while the tissue pushes (per mm along the shaft; the same per mm of the
        // tip's sideways motion, 60 mm beyond the pivot, about the pivot).
        constexpr double kLeverM = 0.06;
        const double b = m_params.dampingNsPerMm * 1e3; // N s/m
        generalized[0] -= b * m_velocity[0];
        generalized[1] -= b * kLeverM * kLeverM * m_velocity[1];
        generalized[2] -= b * kLeverM * kLeverM * m_velocity[2];
    }
    command.insertionForceN = generalized[0];
    command.pitchTorqueNmm = generalized[1] * 1e3;
    command.yawTorqueNmm = generalized[2] * 1e3;
    command.rollTorqueNmm = 0.0; // a frictionless shaft: no torque about it
    command.tipForceN = tip;
    return command;
}

} // namespace hs::haptics
