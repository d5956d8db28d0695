// The stalk of a pedunculated pathology: the way it hangs, clear of the pathologies planned before it.
#include "PathologySteps.h"

#include "Geometry.h"

#include <algorithm>
#include <cmath>

namespace hs::pathology::detail {

namespace {

constexpr double kLeaveWall = 0.35; ///< a stalk leaves the wall at least this much (cosine to the wall's normal)

/// The growth direction of a stalk into the cavity: away from the wall and down towards the internal os, the way
/// a pedunculated polyp hangs in the cavity.
Vec3 stalkDirection(const OrganInfo& info, const Vec3& intoWall) {
    const Vec3 down = -info.axis - intoWall * dot(-info.axis, intoWall);
    if (norm(down) < 0.3)
        return -intoWall;
    return normalized(-intoWall * 0.85 + normalized(down) * 0.5);
}

/// How far the middle of a stalk of `length` from `root` along `dir` stays from the organ's walls (mm, negative in
/// tissue, at most `cutoff`).
double midStalkRoom(const OrganInfo& info, const Bounds& box, const Vec3& root, const Vec3& dir, double length,
                    double cutoff) {
    return signedDistance(*info.mesh, box, root + dir * (0.5 * length), cutoff);
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

/// The stalk's direction: the way it hangs (stalkDirection), or, when that runs into a wall within half the stalk's
/// length or into a pathology planned before it, the nearest direction (tilted in 15 degree steps, still leaving the
/// wall) that does neither; among the clear directions of a tilt, the one closest to the cavity's plane (least
/// anteroposterior): the cavity is flat, so a head tilted towards the anterior or posterior wall would stand in it.
/// A wall that the stalk itself runs into lies below the heights the far wall's push moves (from 1.5 mm): at the tip
/// of a narrow cornual horn a stalk that hangs down along the horn stays in its side wall and is measured as the base
/// of a sessile polyp. When no direction is clear of both, the one clear of the earlier pathologies (or the one that
/// keeps the most room from them).
Vec3 freeStalkDirection(const OrganInfo& info, const Seat& seat, double reach, double radius, double stalkRadius,
                        double gap, const std::vector<const SurfaceMesh*>& earlier) {
    const Vec3 hang = stalkDirection(info, seat.intoWall);
    const double stalk = reach - radius;
    const Bounds organBox = bounds(*info.mesh);
    auto opens = [&](const Vec3& dir) {
        return midStalkRoom(info, organBox, seat.endometrium, dir, stalk, stalkRadius + 1.0) >= stalkRadius;
    };
    double best = stalkClearance(seat.endometrium, hang, reach, radius, stalkRadius, earlier);
    if (best >= gap && opens(hang))
        return hang;
    Vec3 e1, e2;
    orthonormalFrame(hang, e1, e2);
    constexpr double kDegree = 3.14159265358979323846 / 180.0;
    auto search = [&](bool needRun, Vec3& bestDir) {
        for (int tilt = 15; tilt <= 60; tilt += 15) {
            double flattest = 2.0;
            for (int azimuth = 0; azimuth < 360; azimuth += 30) {
                const double a = azimuth * kDegree, t = tilt * kDegree;
                const Vec3 dir = normalized(hang * std::cos(t) + (e1 * std::cos(a) + e2 * std::sin(a)) * std::sin(t));
                if (dot(dir, -seat.intoWall) < kLeaveWall || (needRun && !opens(dir)))
                    continue;
                const double clear = stalkClearance(seat.endometrium, dir, reach, radius, stalkRadius, earlier);
                const double ap = std::fabs(dot(dir, info.anterior));
                if (clear >= gap ? ap < flattest : (!needRun && flattest > 1.0 && clear > best)) {
                    if (clear >= gap)
                        flattest = ap;
                    best = std::max(best, clear);
                    bestDir = dir;
                }
            }
            if (flattest <= 1.0)
                return true;
        }
        return false;
    };
    Vec3 bestDir = hang;
    if (search(true, bestDir))
        return bestDir;
    if (best >= gap)
        return hang; // clear of the earlier pathologies; no direction both opens and is
    bestDir = hang;
    search(false, bestDir);
    return bestDir;
}

} // namespace hs::pathology::detail
