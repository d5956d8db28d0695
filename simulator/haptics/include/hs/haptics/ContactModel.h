#pragma once
/// The haptics loop's local force model: a god-object (proxy) for the scope's tip against the newest HapticFrame
/// (Zilles & Salisbury 1995, "A constraint-based god-object method for haptic display"; Ruspini et al. 1997 for the
/// sphere-shaped proxy). The proxy is a sphere of the scope's radius that follows the device's tip but never passes
/// through the surface: it moves towards the tip until it meets the surface offset by the radius, then slides along
/// it. The force is a spring from the tip to the proxy (the frame's contact stiffness) with a little damping along
/// the contact normal, plus a pivot spring against pitch and yaw. No wall force once the frame says perforated.
///
/// Not thread-safe: one model per haptics loop. No allocation per tick once warmed up.

#include "hs/core/Vec3.h"
#include "hs/haptics/HapticDevice.h"
#include "hs/sim/Device.h"
#include "hs/sim/HapticFrame.h"

#include <cstdint>
#include <vector>

namespace hs::haptics {

struct ContactParams {
    double dampingNsPerMm = 0.001; ///< N*s/mm along the contact normal (1 N at 1 m/s into the wall)
    double velocityFilter = 0.2;   ///< 0..1, weight of the newest tip velocity in its low-pass estimate
    double searchMarginMm = 2.0;   ///< mm, triangles this far beyond the proxy's path are candidates
    int maxConstraints = 3;        ///< surface planes the proxy slides along at once (3: a corner)
};

struct ContactState {
    bool touching = false;
    double depthMm = 0.0; ///< mm, tip to proxy
    Vec3 proxyMm;
    std::size_t candidates = 0; ///< triangles examined closely this tick
};

class ContactModel {
public:
    explicit ContactModel(ContactParams params = {});
    /// The force for `sample` against `frame`; `dtS` the time since the previous update (for the velocity).
    /// The command is enabled with every value finite (not yet clamped to a device).
    ForceCommand update(const sim::HapticFrame& frame, const sim::DeviceSample& sample, double dtS);
    /// Forgets the proxy (the next update starts it at the tip).
    void reset();
    const ContactState& state() const { return m_state; }

private:
    struct Plane {
        Vec3 normal;
        double offset = 0.0; ///< the proxy's centre stays where dot(normal, x) >= offset
    };
    void gatherCandidates(const sim::HapticFrame& frame, const Vec3& from, const Vec3& to, double radius);
    Vec3 pushOut(const sim::HapticFrame& frame, Vec3 p, double radius) const;
    Vec3 slide(const sim::HapticFrame& frame, Vec3 p, const Vec3& goal, double radius);

    ContactParams m_params;
    ContactState m_state;
    bool m_hasProxy = false;
    Vec3 m_proxy;
    Vec3 m_previousTip;
    Vec3 m_velocity; ///< mm/s, filtered
    std::vector<std::int32_t> m_candidates;
    std::vector<Plane> m_planes;
};

} // namespace hs::haptics
