// The stalk of a pedunculated pathology: the way it hangs, clear of the pathologies planned before it.
#include "PathologySteps.h"

#include "Geometry.h"

#include <algorithm>
#include <cmath>

namespace hs::pathology::detail {

namespace {

/// The growth direction of a stalk into the cavity: away from the wall and down towards the internal os, the way
/// a pedunculated polyp hangs in the cavity.
Vec3 stalkDirection(const OrganInfo& info, const Vec3& intoWall) {
    const Vec3 down = -info.axis - intoWall * dot(-info.axis, intoWall);
    if (norm(down) < 0.3)
        return -intoWall;
    return normalized(-intoWall * 0.85 + normalized(down) * 0.5);
}

/// How far a head of `radius` at the end of a stalk from `root` along `dir` stays from the pathologies planned
/// before it (mm; large when there are none).
double stalkClearance(const Vec3& root, const Vec3& dir, double reach, double radius, double stalkRadius,
                      const std::vector<const SurfaceMesh*>& earlier) {
    double worst = 1e9;
    for (const SurfaceMesh* other : earlier) {
        const Bounds box = bounds(*other);
        const double cutoff = 2.0 * radius + 10.0;
        worst = std::min(worst, signedDistance(*other, box, root + dir * reach, cutoff) - radius);
        for (double t = 0.25; t < 0.8; t += 0.25)
            worst = std::min(worst, signedDistance(*other, box, root + dir * (t * reach), cutoff) - stalkRadius);
    }
    return worst;
}

} // namespace

/// The stalk's direction: the way it hangs (stalkDirection), or, when that runs into a pathology planned before
/// it, the nearest direction (tilted in 15 degree steps, still leaving the wall) whose head keeps `gap` from it.
/// Among the clear directions of a tilt, the one that stays closest to the cavity's plane (least anteroposterior):
/// the cavity is flat, so a head tilted towards the anterior or posterior wall would stand in it.
Vec3 freeStalkDirection(const OrganInfo& info, const Seat& seat, double reach, double radius, double stalkRadius,
                        double gap, const std::vector<const SurfaceMesh*>& earlier) {
    const Vec3 hang = stalkDirection(info, seat.intoWall);
    double best = stalkClearance(seat.endometrium, hang, reach, radius, stalkRadius, earlier);
    if (best >= gap)
        return hang;
    Vec3 bestDir = hang, e1, e2;
    orthonormalFrame(hang, e1, e2);
    constexpr double kDegree = 3.14159265358979323846 / 180.0;
    for (int tilt = 15; tilt <= 60; tilt += 15) {
        double flattest = 2.0;
        for (int azimuth = 0; azimuth < 360; azimuth += 30) {
            const double a = azimuth * kDegree, t = tilt * kDegree;
            const Vec3 dir = normalized(hang * std::cos(t) + (e1 * std::cos(a) + e2 * std::sin(a)) * std::sin(t));
            if (dot(dir, -seat.intoWall) < 0.35)
                continue;
            const double clear = stalkClearance(seat.endometrium, dir, reach, radius, stalkRadius, earlier);
            const double ap = std::fabs(dot(dir, info.anterior));
            if (clear >= gap ? ap < flattest : (flattest > 1.0 && clear > best)) {
                if (clear >= gap)
                    flattest = ap;
                best = std::max(best, clear);
                bestDir = dir;
            }
        }
        if (flattest <= 1.0)
            break;
    }
    return bestDir;
}

} // namespace hs::pathology::detail
