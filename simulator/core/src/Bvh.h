#pragma once
// A bounding-volume hierarchy over the triangles of a deforming surface: built once for its topology, refitted to
// new point positions every step (the topology may change later, e.g. by cutting: then it is rebuilt).

#include "hs/core/SurfaceMesh.h"
#include "hs/core/TriangleGeometry.h"
#include "hs/core/Vec3.h"

#include <cstdint>
#include <vector>

namespace hs::sim::detail {

class TriangleBvh {
public:
    /// Builds the tree over `triangles` with the positions `points` (median splits; deterministic).
    /// `skip` (empty, or one flag per triangle): triangles left out of the tree (faces a cut removed); their indices
    /// are never returned.
    void build(const std::vector<Triangle>& triangles, const std::vector<Vec3>& points,
               const std::vector<char>& skip = {});
    /// Recomputes every box for new positions of the same points.
    void refit(const std::vector<Vec3>& points);
    /// Appends to `out` the triangles whose box comes within `radius` of `centre`.
    void near(const Vec3& centre, double radius, std::vector<std::int32_t>& out) const;
    /// The first triangle a ray from `origin` along the unit `direction` hits within `maxT` (positions `points`, those
    /// of the last refit): its index (-1: none); `t` is set to the distance, `u`, `v` to the barycentric coordinates
    /// of its points 1 and 2.
    std::int32_t raycast(const std::vector<Vec3>& points, const Vec3& origin, const Vec3& direction, double maxT,
                         double& t, double& u, double& v) const;
    bool empty() const { return nodes_.empty(); }

private:
    struct Node {
        Vec3 lo, hi;
        std::int32_t left = -1, right = -1; ///< children; -1 for a leaf
        std::int32_t first = 0, count = 0;  ///< a leaf's range in order_
    };
    std::int32_t buildNode(std::int32_t first, std::int32_t count, const std::vector<Vec3>& centres);
    void refitNode(std::int32_t node, const std::vector<Vec3>& points);
    const std::vector<Triangle>* triangles_ = nullptr;
    std::vector<Triangle> own_;
    std::vector<std::int32_t> order_;
    std::vector<Node> nodes_;
};

} // namespace hs::sim::detail
