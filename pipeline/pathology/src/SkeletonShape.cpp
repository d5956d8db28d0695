// The skeleton growth model: a contour revolved around a skeleton curve, with seeded lobulation.
#include "Shapes.h"

#include "Geometry.h"

#include <algorithm>
#include <cmath>

namespace hs::pathology::detail {

namespace {

constexpr int kAround = 48; ///< vertices per ring of a revolved contour

double smin(double a, double b, double k) {
    const double h = std::max(k - std::fabs(a - b), 0.0) / k;
    return std::min(a, b) - h * h * k * 0.25;
}

/// The 2-D contour of a revolved shape: signed distance in the (s, r) half plane.
struct Profile {
    bool stalked = false;
    double length = 0.0; ///< s of the head centre (stalked) or half-length (ellipsoid)
    double radius = 0.0; ///< head / equatorial radius
    double stalkRadius = 0.0;
    double eval(double s, double r) const {
        if (!stalked) {
            const double q = std::sqrt((s / length) * (s / length) + (r / radius) * (r / radius));
            return (q - 1.0) * std::min(length, radius);
        }
        const double sc = std::clamp(s, 0.0, length);
        const double capsule = std::sqrt((s - sc) * (s - sc) + r * r) - stalkRadius;
        const double head = std::sqrt((s - length) * (s - length) + r * r) - radius;
        return smin(capsule, head, 0.6 * stalkRadius + 0.15 * radius);
    }
    /// Radius of the contour at s (0 outside).
    double radiusAt(double s) const {
        if (eval(s, 0.0) >= 0.0)
            return 0.0;
        double lo = 0.0, hi = 3.0 * (radius + stalkRadius);
        for (int it = 0; it < 50; ++it) {
            const double mid = 0.5 * (lo + hi);
            (eval(s, mid) < 0.0 ? lo : hi) = mid;
        }
        return 0.5 * (lo + hi);
    }
};

/// Contour points (s, r) from pole to pole, resampled uniformly by arc length.
std::vector<std::pair<double, double>> contour(const Profile& p, double sLo, double sHi, double spacing) {
    const int n = 800;
    std::vector<std::pair<double, double>> dense;
    double first = 0.0, last = 0.0;
    bool inside = false;
    double prevS = sLo;
    for (int i = 0; i <= n; ++i) {
        const double s = sLo + (sHi - sLo) * i / n;
        const bool in = p.eval(s, 0.0) < 0.0;
        if (in && !inside) { // refine the entry pole
            double lo = prevS, hi = s;
            for (int it = 0; it < 50; ++it) {
                const double mid = 0.5 * (lo + hi);
                (p.eval(mid, 0.0) < 0.0 ? hi : lo) = mid;
            }
            first = hi;
            dense.emplace_back(first, 0.0);
        }
        if (in)
            dense.emplace_back(s, p.radiusAt(s));
        if (!in && inside) {
            double lo = prevS, hi = s;
            for (int it = 0; it < 50; ++it) {
                const double mid = 0.5 * (lo + hi);
                (p.eval(mid, 0.0) < 0.0 ? lo : hi) = mid;
            }
            last = lo;
            dense.emplace_back(last, 0.0);
            break;
        }
        inside = in;
        prevS = s;
    }
    std::vector<double> arc(dense.size(), 0.0);
    for (std::size_t i = 1; i < dense.size(); ++i)
        arc[i] = arc[i - 1] + std::hypot(dense[i].first - dense[i - 1].first, dense[i].second - dense[i - 1].second);
    const double total = arc.back();
    const int stations = std::max(10, static_cast<int>(std::lround(total / spacing)));
    std::vector<std::pair<double, double>> out;
    out.push_back(dense.front());
    std::size_t seg = 1;
    for (int k = 1; k < stations; ++k) {
        const double a = total * k / stations;
        while (seg + 1 < arc.size() && arc[seg] < a)
            ++seg;
        const double t = (a - arc[seg - 1]) / std::max(arc[seg] - arc[seg - 1], 1e-12);
        out.emplace_back(dense[seg - 1].first + t * (dense[seg].first - dense[seg - 1].first),
                         dense[seg - 1].second + t * (dense[seg].second - dense[seg - 1].second));
    }
    out.push_back(dense.back());
    return out;
}

} // namespace

SurfaceMesh skeletonShape(const ShapeSpec& spec, Rng& rng) {
    Profile profile;
    Vec3 start, dir, bendDir;
    double bend = 0.0;
    const bool stalked = spec.polyp || spec.pedunculated;
    if (stalked) {
        profile.stalked = true;
        profile.length = distance(spec.center, spec.base);
        profile.radius = spec.radius;
        profile.stalkRadius = spec.stalkRadius;
        start = spec.base;
        dir = normalized(spec.center - spec.base);
        Vec3 e1, e2;
        orthonormalFrame(dir, e1, e2);
        const double angle = rng.uniform(0.0, 2.0 * kPi);
        bendDir = e1 * std::cos(angle) + e2 * std::sin(angle);
        bend = spec.pedunculated || profile.length > 1.5 * spec.radius ? rng.uniform(0.05, 0.2) * profile.length : 0.0;
        // The bow's curvature peaks at 2 pi^2 bend / L^2 (L the bowed length); its radius stays above the stalk's
        // radius plus a few millimetres, or the stalk's inner side (and any offset of it) would fold.
        const double bowed = std::max(profile.length - profile.radius, 0.3 * profile.length);
        bend = std::min(bend, bowed * bowed / (2.0 * kPi * kPi * (profile.stalkRadius + 3.0)));
    } else {
        // A myoma: an ellipsoid of revolution whose axis lies mostly in the wall's tangent plane (across the wall
        // for a transmural one, which must reach both its surfaces).
        Vec3 e1, e2;
        orthonormalFrame(spec.intoWall, e1, e2);
        const double angle = rng.uniform(0.0, 2.0 * kPi);
        const Vec3 tangent = e1 * std::cos(angle) + e2 * std::sin(angle);
        dir = spec.transmural ? normalized(spec.intoWall + tangent * rng.uniform(0.0, 0.1))
                              : normalized(tangent + spec.intoWall * rng.uniform(-0.3, 0.3));
        profile.length = spec.radius * rng.uniform(1.0, 1.2);
        profile.radius = spec.radius;
        start = spec.center;
    }
    const double sLo = stalked ? -profile.stalkRadius - 1.0 : -profile.length - 1.0;
    const double sHi = stalked ? profile.length + profile.radius + 1.0 : profile.length + 1.0;
    const auto stations = contour(profile, sLo, sHi, 2.0 * kPi * spec.radius / kAround);

    // Lobulation: a few harmonics around and along the axis (polyps are more lobulated than myomas).
    const double amplitude = spec.polyp ? 0.09 : 0.05;
    struct Lobe {
        double weight, k, phase, axial, axialPhase;
    };
    std::vector<Lobe> lobes;
    double weightSum = 0.0;
    for (int k = 2; k <= 5; ++k) {
        Lobe l{rng.uniform(0.3, 1.0) / std::sqrt(static_cast<double>(k)), static_cast<double>(k),
               rng.uniform(0.0, 2.0 * kPi), rng.uniform(0.5, 1.5), rng.uniform(0.0, 2.0 * kPi)};
        weightSum += l.weight;
        lobes.push_back(l);
    }
    const double headStart = stalked ? profile.length - profile.radius : -1e300;
    auto curve = [&](double s) {
        if (bend == 0.0)
            return start + dir * s;
        // The stalk bows out and back before the head starts, so the head's rings stay parallel.
        const double x = std::clamp(s / std::max(profile.length - profile.radius, 0.3 * profile.length), 0.0, 1.0);
        return start + dir * s + bendDir * (bend * 0.5 * (1.0 - std::cos(2.0 * kPi * x)));
    };

    SurfaceMesh mesh;
    mesh.points.push_back(curve(stations.front().first));
    Vec3 prevT = dir, e1, e2;
    orthonormalFrame(dir, e1, e2);
    const std::size_t rings = stations.size() - 2;
    for (std::size_t k = 1; k + 1 < stations.size(); ++k) {
        const double s = stations[k].first, r = stations[k].second;
        const Vec3 tangent = normalized(curve(s + 1e-3) - curve(s - 1e-3));
        // Rotation-minimizing frame: project the previous normal onto the new normal plane.
        e1 = normalized(e1 - tangent * dot(e1, tangent));
        e2 = cross(tangent, e1);
        prevT = tangent;
        const double head = stalked ? smoothstep(headStart, headStart + 0.6 * profile.radius, s) : 1.0;
        const double along = stalked ? (s - profile.length) / profile.radius : s / profile.length;
        for (int j = 0; j < kAround; ++j) {
            const double theta = 2.0 * kPi * j / kAround;
            double m = 0.0;
            for (const Lobe& l : lobes)
                m += l.weight * std::cos(l.k * theta + l.phase) * std::cos(l.axial * kPi * along + l.axialPhase);
            const double rr = r * (1.0 + amplitude * head * m / weightSum);
            mesh.points.push_back(curve(s) + (e1 * std::cos(theta) + e2 * std::sin(theta)) * rr);
        }
    }
    (void)prevT;
    mesh.points.push_back(curve(stations.back().first));
    const auto ring = [&](std::size_t k, int j) {
        return static_cast<std::int32_t>(1 + k * kAround + static_cast<std::size_t>((j + kAround) % kAround));
    };
    const auto lastPole = static_cast<std::int32_t>(mesh.points.size() - 1);
    for (int j = 0; j < kAround; ++j) {
        mesh.triangles.push_back({0, ring(0, j), ring(0, j + 1)});
        for (std::size_t k = 0; k + 1 < rings; ++k) {
            mesh.triangles.push_back({ring(k, j), ring(k + 1, j), ring(k + 1, j + 1)});
            mesh.triangles.push_back({ring(k, j), ring(k + 1, j + 1), ring(k, j + 1)});
        }
        mesh.triangles.push_back({lastPole, ring(rings - 1, j + 1), ring(rings - 1, j)});
    }
    orientOutward(mesh);
    return mesh;
}

} // namespace hs::pathology::detail
