#include "Bvh.h"

#include <algorithm>
#include <cmath>

namespace hs::sim::detail {

namespace {

constexpr std::int32_t kLeafSize = 4;

Vec3 minOf(const Vec3& a, const Vec3& b) {
    return {std::min(a.x, b.x), std::min(a.y, b.y), std::min(a.z, b.z)};
}
Vec3 maxOf(const Vec3& a, const Vec3& b) {
    return {std::max(a.x, b.x), std::max(a.y, b.y), std::max(a.z, b.z)};
}

double boxDistanceSquared(const Vec3& p, const Vec3& lo, const Vec3& hi) {
    const double dx = std::max({lo.x - p.x, 0.0, p.x - hi.x});
    const double dy = std::max({lo.y - p.y, 0.0, p.y - hi.y});
    const double dz = std::max({lo.z - p.z, 0.0, p.z - hi.z});
    return dx * dx + dy * dy + dz * dz;
}

/// Whether the ray enters the box before `maxT` (slab test).
bool rayHitsBox(const Vec3& o, const Vec3& inv, const Vec3& lo, const Vec3& hi, double maxT) {
    double t0 = 0.0, t1 = maxT;
    const double os[3] = {o.x, o.y, o.z}, is[3] = {inv.x, inv.y, inv.z}, ls[3] = {lo.x, lo.y, lo.z},
                 hs[3] = {hi.x, hi.y, hi.z};
    for (int k = 0; k < 3; ++k) {
        double a = (ls[k] - os[k]) * is[k];
        double b = (hs[k] - os[k]) * is[k];
        if (a > b)
            std::swap(a, b);
        t0 = std::max(t0, a);
        t1 = std::min(t1, b);
        if (t0 > t1)
            return false;
    }
    return true;
}

} // namespace

void TriangleBvh::build(const std::vector<Triangle>& triangles, const std::vector<Vec3>& points,
                        const std::vector<char>& skip) {
    own_ = triangles;
    triangles_ = &own_;
    nodes_.clear();
    order_.clear();
    order_.reserve(triangles.size());
    std::vector<Vec3> centres(triangles.size());
    for (std::size_t i = 0; i < triangles.size(); ++i) {
        const Triangle& t = triangles[i];
        centres[i] = (points[static_cast<std::size_t>(t[0])] + points[static_cast<std::size_t>(t[1])] +
                      points[static_cast<std::size_t>(t[2])]) /
                     3.0;
        if (skip.size() != triangles.size() || !skip[i])
            order_.push_back(static_cast<std::int32_t>(i));
    }
    if (!order_.empty())
        buildNode(0, static_cast<std::int32_t>(order_.size()), centres);
    refit(points);
}

std::int32_t TriangleBvh::buildNode(std::int32_t first, std::int32_t count, const std::vector<Vec3>& centres) {
    const auto index = static_cast<std::int32_t>(nodes_.size());
    nodes_.push_back({});
    nodes_.back().first = first;
    nodes_.back().count = count;
    if (count <= kLeafSize)
        return index;
    Vec3 lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
    for (std::int32_t i = first; i < first + count; ++i) {
        lo = minOf(lo, centres[static_cast<std::size_t>(order_[static_cast<std::size_t>(i)])]);
        hi = maxOf(hi, centres[static_cast<std::size_t>(order_[static_cast<std::size_t>(i)])]);
    }
    const Vec3 size = hi - lo;
    const int axis = size.x >= size.y && size.x >= size.z ? 0 : (size.y >= size.z ? 1 : 2);
    const auto key = [&centres, axis](std::int32_t t) {
        const Vec3& c = centres[static_cast<std::size_t>(t)];
        return axis == 0 ? c.x : (axis == 1 ? c.y : c.z);
    };
    const std::int32_t half = count / 2;
    std::nth_element(order_.begin() + first, order_.begin() + first + half, order_.begin() + first + count,
                     [&key](std::int32_t a, std::int32_t b) { return key(a) < key(b) || (key(a) == key(b) && a < b); });
    const std::int32_t left = buildNode(first, half, centres);
    const std::int32_t right = buildNode(first + half, count - half, centres);
    nodes_[static_cast<std::size_t>(index)].left = left;
    nodes_[static_cast<std::size_t>(index)].right = right;
    return index;
}

void TriangleBvh::refit(const std::vector<Vec3>& points) {
    if (!nodes_.empty())
        refitNode(0, points);
}

void TriangleBvh::refitNode(std::int32_t index, const std::vector<Vec3>& points) {
    Node& node = nodes_[static_cast<std::size_t>(index)];
    if (node.left < 0) {
        Vec3 lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
        for (std::int32_t i = node.first; i < node.first + node.count; ++i) {
            const Triangle& t = (*triangles_)[static_cast<std::size_t>(order_[static_cast<std::size_t>(i)])];
            for (const std::int32_t v : t) {
                lo = minOf(lo, points[static_cast<std::size_t>(v)]);
                hi = maxOf(hi, points[static_cast<std::size_t>(v)]);
            }
        }
        node.lo = lo;
        node.hi = hi;
        return;
    }
    refitNode(node.left, points);
    refitNode(node.right, points);
    const Node& l = nodes_[static_cast<std::size_t>(node.left)];
    const Node& r = nodes_[static_cast<std::size_t>(node.right)];
    node.lo = minOf(l.lo, r.lo);
    node.hi = maxOf(l.hi, r.hi);
}

void TriangleBvh::near(const Vec3& centre, double radius, std::vector<std::int32_t>& out) const {
    if (nodes_.empty())
        return;
    const double r2 = radius * radius;
    std::int32_t stack[128];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const Node& node = nodes_[static_cast<std::size_t>(stack[--top])];
        if (boxDistanceSquared(centre, node.lo, node.hi) > r2)
            continue;
        if (node.left < 0) {
            for (std::int32_t i = node.first; i < node.first + node.count; ++i)
                out.push_back(order_[static_cast<std::size_t>(i)]);
        } else if (top + 2 <= 128) {
            stack[top++] = node.right;
            stack[top++] = node.left;
        }
    }
}

std::int32_t TriangleBvh::raycast(const std::vector<Vec3>& points, const Vec3& origin, const Vec3& direction,
                                  double maxT, double& t, double& u, double& v) const {
    if (nodes_.empty())
        return -1;
    const auto inverse = [](double x) { return std::abs(x) < 1e-300 ? 1e300 : 1.0 / x; };
    const Vec3 inv{inverse(direction.x), inverse(direction.y), inverse(direction.z)};
    std::int32_t best = -1;
    double bestT = maxT;
    std::int32_t stack[128];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const Node& node = nodes_[static_cast<std::size_t>(stack[--top])];
        if (!rayHitsBox(origin, inv, node.lo, node.hi, bestT))
            continue;
        if (node.left < 0) {
            for (std::int32_t i = node.first; i < node.first + node.count; ++i) {
                const std::int32_t f = order_[static_cast<std::size_t>(i)];
                const Triangle& tri = (*triangles_)[static_cast<std::size_t>(f)];
                double ht = 0.0, hu = 0.0, hv = 0.0;
                if (hs::rayTriangle(origin, direction, points[static_cast<std::size_t>(tri[0])],
                                    points[static_cast<std::size_t>(tri[1])], points[static_cast<std::size_t>(tri[2])],
                                    0.0, ht, hu, hv) &&
                    (ht < bestT || (ht == bestT && f < best))) {
                    best = f;
                    bestT = ht;
                    u = hu;
                    v = hv;
                }
            }
        } else if (top + 2 <= 128) {
            stack[top++] = node.right;
            stack[top++] = node.left;
        }
    }
    t = bestT;
    return best;
}

} // namespace hs::sim::detail
