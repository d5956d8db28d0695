// The scope passage's landmarks from the canal and ostium faces of a scene's visual surface.

#include "hs/scene/Scene.h"
#include "hs/scene/ScopePassage.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>

namespace hs::scene {

namespace {

struct FacePoints {
    std::vector<Vec3> centroids;
    std::vector<double> weights; ///< face areas (1 each when every face is degenerate)
};

Result<FacePoints> facePoints(const SurfaceMesh& surface, const std::vector<std::int32_t>& faces, const char* what) {
    if (faces.empty())
        return fail(ErrorCode::InvalidInput, std::string("scope passage: the surface has no ") + what + " faces");
    FacePoints out;
    double total = 0.0;
    for (std::int32_t f : faces) {
        if (f < 0 || std::size_t(f) >= surface.faceCount())
            return fail(ErrorCode::InvalidInput, std::string("scope passage: ") + what + " face " + std::to_string(f) +
                                                     " is outside 0.." + std::to_string(surface.faceCount()));
        const auto& t = surface.triangles[std::size_t(f)];
        const Vec3 &a = surface.points[std::size_t(t[0])], &b = surface.points[std::size_t(t[1])],
                   &c = surface.points[std::size_t(t[2])];
        out.centroids.push_back((a + b + c) / 3.0);
        out.weights.push_back(0.5 * norm(cross(b - a, c - a)));
        total += out.weights.back();
    }
    if (!(total > 0.0))
        std::fill(out.weights.begin(), out.weights.end(), 1.0);
    return out;
}

Vec3 weightedMean(const FacePoints& p) {
    Vec3 sum;
    double w = 0.0;
    for (std::size_t i = 0; i < p.centroids.size(); ++i) {
        sum += p.centroids[i] * p.weights[i];
        w += p.weights[i];
    }
    return sum / w;
}

/// Principal direction of the points (largest eigenvector of their weighted covariance, by power iteration from the
/// covariance's largest column, so the start is never orthogonal to it); zero when the points do not spread.
Vec3 principalDirection(const FacePoints& p, const Vec3& mean) {
    std::array<Vec3, 3> cov{};
    for (std::size_t i = 0; i < p.centroids.size(); ++i) {
        const Vec3 d = p.centroids[i] - mean;
        for (int r = 0; r < 3; ++r)
            cov[std::size_t(r)] += d * (d[r] * p.weights[i]);
    }
    Vec3 v = cov[0];
    for (const Vec3& column : cov)
        if (norm2(column) > norm2(v))
            v = column;
    if (!(norm2(v) > 1e-18))
        return {};
    for (int it = 0; it < 200; ++it)
        v = normalized(Vec3(dot(cov[0], v), dot(cov[1], v), dot(cov[2], v)));
    return v;
}

/// Mean of the canal's vertices whose projection on `axis` lies within `bandMm` of `s` (one end of the tube).
Vec3 endCentre(const std::vector<Vec3>& vertices, const Vec3& mean, const Vec3& axis, double s, double bandMm) {
    Vec3 sum;
    double count = 0.0;
    for (const Vec3& v : vertices)
        if (std::fabs(dot(v - mean, axis) - s) <= bandMm) {
            sum += v;
            count += 1.0;
        }
    return sum / count;
}

/// The distinct vertices of `faces` (already checked to be in range), in ascending index order.
std::vector<Vec3> faceVertices(const SurfaceMesh& surface, const std::vector<std::int32_t>& faces) {
    std::vector<std::int32_t> ids;
    for (std::int32_t f : faces)
        ids.insert(ids.end(), surface.triangles[std::size_t(f)].begin(), surface.triangles[std::size_t(f)].end());
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
    std::vector<Vec3> points;
    for (std::int32_t v : ids)
        points.push_back(surface.points[std::size_t(v)]);
    return points;
}

/// Two halves of the ostium faces this close are one ostium: an ostium spans a few triangles, a millimetre or two,
/// while the two lie 25-40 mm apart across the cavity (Chen et al., docs/references.md [Chen2020]).
constexpr double kMinOstiaDistanceMm = 5.0;

/// Midpoint of the two ostia: the ostium faces split by the sign of their offset along their principal direction
/// (one ostium left, one right). When the two halves lie closer than kMinOstiaDistanceMm they are one ostium, and
/// its centre is returned with count 1.
Vec3 ostiaMidpoint(const FacePoints& ostia, int& count) {
    const Vec3 mean = weightedMean(ostia);
    const Vec3 across = principalDirection(ostia, mean);
    FacePoints sides[2];
    for (std::size_t i = 0; i < ostia.centroids.size(); ++i) {
        const int side = dot(ostia.centroids[i] - mean, across) >= 0.0 ? 1 : 0;
        sides[side].centroids.push_back(ostia.centroids[i]);
        sides[side].weights.push_back(ostia.weights[i]);
    }
    count = 1;
    if (sides[0].centroids.empty() || sides[1].centroids.empty())
        return mean;
    const Vec3 a = weightedMean(sides[0]), b = weightedMean(sides[1]);
    if (distance(a, b) < kMinOstiaDistanceMm)
        return mean;
    count = 2;
    return (a + b) * 0.5;
}

} // namespace

Result<ScopeLandmarks> findScopeLandmarks(const SurfaceMesh& surface, const std::vector<std::int32_t>& canalFaces,
                                          const std::vector<std::int32_t>& ostiumFaces) {
    if (auto valid = validate(surface); !valid.ok())
        return fail(ErrorCode::InvalidInput, "scope passage: invalid surface: " + valid.error().detail);
    auto canal = facePoints(surface, canalFaces, "cervical-canal");
    if (!canal.ok())
        return canal.failure();
    auto ostia = facePoints(surface, ostiumFaces, "ostium");
    if (!ostia.ok())
        return ostia.failure();

    const Vec3 mean = weightedMean(*canal);
    Vec3 axis = principalDirection(*canal, mean);
    if (norm2(axis) == 0.0)
        return fail(ErrorCode::InvalidInput, "scope passage: the cervical-canal faces do not spread; no canal axis");
    const std::vector<Vec3> vertices = faceVertices(surface, canalFaces);
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (const Vec3& v : vertices) {
        lo = std::min(lo, dot(v - mean, axis));
        hi = std::max(hi, dot(v - mean, axis));
    }
    // Each os from the vertices in the last twentieth of the canal's extent along its axis: the rim of the tube.
    const double band = 0.05 * (hi - lo);
    Vec3 a = endCentre(vertices, mean, axis, lo, band);
    Vec3 b = endCentre(vertices, mean, axis, hi, band);
    int ostiaFound = 0;
    const Vec3 fundus = ostiaMidpoint(*ostia, ostiaFound);
    if (distance(a, fundus) < distance(b, fundus))
        std::swap(a, b);
    return ScopeLandmarks{a, b, fundus, ostiaFound};
}

Result<ScopeLandmarks> findScopeLandmarks(const Scene& scene) {
    std::vector<std::int32_t> canal, ostia;
    for (const auto& label : scene.labels) {
        if (label.element != LabelElement::SurfaceFace)
            continue;
        if (label.kind == LabelKind::CervicalCanal)
            canal.insert(canal.end(), label.indices.begin(), label.indices.end());
        else if (label.kind == LabelKind::Ostium)
            ostia.insert(ostia.end(), label.indices.begin(), label.indices.end());
    }
    if (canal.empty())
        return fail(ErrorCode::InvalidInput,
                    "scope passage: the scene has no cervical-canal label on its visual surface (labels.json)");
    if (ostia.empty())
        return fail(ErrorCode::InvalidInput,
                    "scope passage: the scene has no ostium label on its visual surface (labels.json)");
    std::sort(canal.begin(), canal.end());
    std::sort(ostia.begin(), ostia.end());
    return findScopeLandmarks(scene.surface.mesh, canal, ostia);
}

} // namespace hs::scene
