// Shape measures shared by the growth models and the stage.
#include "Shapes.h"

#include "Geometry.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <unordered_map>

namespace hs::pathology::detail {

double headDiameter(const std::vector<Vec3>& points, const Vec3& base, const Vec3& axis, double* stalkLength) {
    if (stalkLength)
        *stalkLength = 0.0;
    double tMin = 1e300, tMax = -1e300;
    for (const Vec3& p : points) {
        tMin = std::min(tMin, dot(p - base, axis));
        tMax = std::max(tMax, dot(p - base, axis));
    }
    const int bins = 40;
    const double w = std::max((tMax - tMin) / bins, 1e-9);
    // A bin's radius is measured from the centre of its own cross-section: a bowed or tilted stalk is as narrow as a
    // straight one.
    std::vector<Vec3> centre(bins);
    std::vector<double> count(bins, 0.0), radius(bins, 0.0);
    auto binOf = [&](const Vec3& p) {
        return static_cast<std::size_t>(std::clamp(static_cast<int>((dot(p - base, axis) - tMin) / w), 0, bins - 1));
    };
    for (const Vec3& p : points) {
        const std::size_t b = binOf(p);
        centre[b] += p - axis * dot(p - base, axis);
        count[b] += 1.0;
    }
    for (std::size_t b = 0; b < centre.size(); ++b)
        if (count[b] > 0.0)
            centre[b] = centre[b] / count[b];
    for (const Vec3& p : points) {
        const std::size_t b = binOf(p);
        const Vec3 offset = p - axis * dot(p - base, axis) - centre[b];
        radius[b] = std::max(radius[b], norm(offset));
    }
    const double maxR = *std::max_element(radius.begin(), radius.end());
    // The stalk: consecutive bins from the wall (t = 0) narrower than half the head.
    int b = std::clamp(static_cast<int>((0.0 - tMin) / w), 0, bins - 1);
    while (b < bins && radius[static_cast<std::size_t>(b)] < 0.5 * maxR)
        ++b;
    const double stalkEnd = tMin + b * w;
    if (stalkEnd < 2.0 || b >= bins) // shorter than 2 mm: sessile
        return diameter(points);
    if (stalkLength)
        *stalkLength = stalkEnd;
    std::vector<Vec3> head;
    for (const Vec3& p : points)
        if (dot(p - base, axis) > stalkEnd)
            head.push_back(p);
    return diameter(head);
}

void emitFrame(const GrowthTuning& tuning, clinical::GrowthModel model, int step, bool last, std::vector<Vec3> points) {
    if (!tuning.observe || !*tuning.observe)
        return;
    GrowthFrame frame;
    frame.pathology = tuning.pathology;
    frame.model = model;
    frame.step = step;
    frame.last = last;
    frame.points = std::move(points);
    (*tuning.observe)(frame);
}

void emitSweptFrames(const GrowthTuning& tuning, const SurfaceMesh& shape, const ShapeSpec& spec) {
    if (!tuning.observe || !*tuning.observe || shape.points.empty())
        return;
    // The contour is revolved station by station along the skeleton, from its root (a stalk's base, or one pole of
    // a myoma's axis): the points in that order, a quarter more each step.
    const Vec3 root = spec.polyp || spec.pedunculated ? spec.base : spec.center;
    const Vec3 axis = spec.polyp || spec.pedunculated ? normalized(spec.center - spec.base) : spec.intoWall;
    std::vector<std::pair<double, Vec3>> along;
    for (const Vec3& p : shape.points)
        along.emplace_back(dot(p - root, axis), p);
    std::sort(along.begin(), along.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    constexpr int kSteps = 4;
    for (int step = 1; step <= kSteps; ++step) {
        std::vector<Vec3> points;
        const std::size_t n = along.size() * static_cast<std::size_t>(step) / kSteps;
        for (std::size_t i = 0; i < n; ++i)
            points.push_back(along[i].second);
        emitFrame(tuning, clinical::GrowthModel::Skeleton, step, step == kSteps, std::move(points));
    }
}

} // namespace hs::pathology::detail
