#include "hs/anatomy/UterusGenerator.h"

#include "hs/core/Units.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace hs::anatomy {

namespace {

/// Ellipsoid formula of clinical ultrasound: V = L * W * AP * pi/6 (0.523).
constexpr double kEllipsoidFactor = 0.523;

struct Reader {
    const SurfaceMesh& mesh;
    const TemplateLayout& l;

    const Vec3& at(int ring, int j) const { return mesh.points[static_cast<std::size_t>(l.vertex(ring, j))]; }
    Vec3 centroid(int ring) const {
        Vec3 c;
        for (int j = 0; j < l.around; ++j)
            c += at(ring, j);
        return c / l.around;
    }
    double lateral(int ring) const { return distance(at(ring, 0), at(ring, l.around / 2)); }
    double sagittal(int ring) const { return distance(at(ring, l.around / 4), at(ring, 3 * l.around / 4)); }
    /// Length of the polyline through the centroids of rings [first, last] (either order).
    double centreline(int first, int last) const {
        double sum = 0.0;
        const int step = last >= first ? 1 : -1;
        for (int r = first; r != last; r += step)
            sum += distance(centroid(r), centroid(r + step));
        return sum;
    }
};

double cavityVolume(const Reader& in) {
    const auto& l = in.l;
    const auto& pts = in.mesh.points;
    // The inner faces (canal, cavity, cap) closed by a fan over the external os.
    double v = 0.0;
    auto add = [&](const Vec3& a, const Vec3& b, const Vec3& c) { v += dot(a, cross(b, c)) / 6.0; };
    const Vec3 os = in.centroid(l.firstCanalRing());
    for (int j = 0; j < l.around; ++j)
        add(os, in.at(l.firstCanalRing(), j), in.at(l.firstCanalRing(), j + 1));
    const std::size_t firstFace = static_cast<std::size_t>(l.around) * (1 + 2 * l.firstCanalRing());
    for (std::size_t f = firstFace; f < in.mesh.triangles.size(); ++f) {
        const auto& t = in.mesh.triangles[f];
        add(pts[static_cast<std::size_t>(t[0])], pts[static_cast<std::size_t>(t[1])],
            pts[static_cast<std::size_t>(t[2])]);
    }
    return std::abs(v);
}

/// Coronal outline of the cavity (both lateral edges from the internal os over the cap), vector area in mm^2.
double cavityArea(const Reader& in) {
    const auto& l = in.l;
    std::vector<Vec3> outline;
    const int last = l.ringCount() - 1;
    for (int r = l.internalOsRing(); r <= last; ++r)
        outline.push_back(in.at(r, 0));
    outline.push_back(in.mesh.points[static_cast<std::size_t>(l.innerPole())]);
    for (int r = last; r >= l.internalOsRing(); --r)
        outline.push_back(in.at(r, l.around / 2));
    Vec3 area;
    for (std::size_t i = 0; i < outline.size(); ++i)
        area += cross(outline[i], outline[(i + 1) % outline.size()]);
    return 0.5 * norm(area);
}

/// The crossing of the line through `p` along the unit `normal` with those of `faces` of `body` that face the same
/// way (so the other side of a thin cavity is never taken for its own wall), nearest to `p` and within `reach` mm.
std::optional<Vec3> reproject(const Vec3& p, const Vec3& normal, const SurfaceMesh& body,
                              const std::vector<std::int32_t>& faces, double reach) {
    std::optional<double> step;
    for (const auto f : faces) {
        const auto& t = body.triangles[static_cast<std::size_t>(f)];
        const Vec3& a = body.points[static_cast<std::size_t>(t[0])];
        const Vec3 e1 = body.points[static_cast<std::size_t>(t[1])] - a;
        const Vec3 e2 = body.points[static_cast<std::size_t>(t[2])] - a;
        if (dot(cross(e1, e2), normal) <= 0.0)
            continue;
        const Vec3 h = cross(normal, e2);
        const double det = dot(e1, h);
        if (std::abs(det) < 1e-15)
            continue;
        const Vec3 s = p - a;
        const double bu = dot(s, h) / det;
        const Vec3 q = cross(s, e1);
        const double bv = dot(normal, q) / det;
        const double tt = dot(e2, q) / det;
        if (bu >= 0.0 && bv >= 0.0 && bu + bv <= 1.0 && std::abs(tt) <= reach &&
            (!step || std::abs(tt) < std::abs(*step)))
            step = tt;
    }
    if (!step)
        return std::nullopt;
    return p + normal * *step;
}

/// The faces of `faces` whose box comes within `margin` of the box of `points`.
std::vector<std::int32_t> facesNear(const std::vector<Vec3>& points, double margin, const SurfaceMesh& body,
                                    const std::vector<std::int32_t>& faces) {
    Vec3 lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
    for (const Vec3& p : points) {
        lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
        hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
    }
    std::vector<std::int32_t> near;
    for (const auto f : faces) {
        const auto& t = body.triangles[static_cast<std::size_t>(f)];
        bool out = false;
        for (int axis = 0; axis < 3 && !out; ++axis) {
            double fl = 1e300, fh = -1e300;
            for (const auto v : t) {
                const Vec3& p = body.points[static_cast<std::size_t>(v)];
                const double c = axis == 0 ? p.x : (axis == 1 ? p.y : p.z);
                fl = std::min(fl, c), fh = std::max(fh, c);
            }
            const double l = axis == 0 ? lo.x : (axis == 1 ? lo.y : lo.z);
            const double h = axis == 0 ? hi.x : (axis == 1 ? hi.y : hi.z);
            out = fh < l - margin || fl > h + margin;
        }
        if (!out)
            near.push_back(f);
    }
    return near;
}

/// A subserosal myoma bulges the serosa, and a pathology's push moves the far wall of the cavity, about this far.
constexpr double kReprojectReachMm = 20.0;

/// Moves the vertices `ids` of `mesh` (a copy of the template instance) along their normals onto `faces` of `body`;
/// a vertex with no crossing stays.
/// Returns how many stayed.
std::size_t reprojectVertices(const std::vector<std::size_t>& ids, const std::vector<Vec3>& normals,
                              const SurfaceMesh& body, const std::vector<std::int32_t>& faces, SurfaceMesh& mesh) {
    std::vector<Vec3> points;
    for (const auto v : ids)
        points.push_back(mesh.points[v]);
    const auto near = facesNear(points, kReprojectReachMm, body, faces);
    std::size_t stayed = 0;
    for (std::size_t k = 0; k < ids.size(); ++k) {
        if (auto hit = reproject(points[k], normals[ids[k]], body, near, kReprojectReachMm))
            mesh.points[ids[k]] = *hit;
        else
            ++stayed;
    }
    return stayed;
}

} // namespace

double ellipsoidVolumeMl(double lengthMm, double widthMm, double apDepthMm) {
    return units::mlFromMm3(lengthMm * widthMm * apDepthMm * kEllipsoidFactor);
}

Result<UterusDimensions> measureBody(const SurfaceMesh& organ, const TemplateLayout& l, const SurfaceMesh& body,
                                     const std::vector<std::int32_t>& serosaFaces,
                                     const std::vector<std::int32_t>& cavityFaces, BodyCrossings* crossings) {
    if (organ.points.size() != static_cast<std::size_t>(l.vertexCount()) ||
        organ.triangles.size() != static_cast<std::size_t>(l.faceCount()))
        return fail(ErrorCode::InvalidInput, "the organ has " + std::to_string(organ.points.size()) +
                                                 " vertices; the uterus template has " +
                                                 std::to_string(l.vertexCount()));
    const auto normals = hs::vertexNormals(organ);
    SurfaceMesh onBody = organ;
    auto ringIds = [&](int r) {
        std::vector<std::size_t> ids;
        for (int j = 0; j < l.around; ++j)
            ids.push_back(static_cast<std::size_t>(l.vertex(r, j)));
        return ids;
    };
    BodyCrossings counted;
    for (int r = 0; r < l.ringCount(); ++r) {
        const bool serosa = r < l.firstCanalRing();
        const std::size_t stayed =
            reprojectVertices(ringIds(r), normals, body, serosa ? serosaFaces : cavityFaces, onBody);
        (serosa ? counted.serosaStayed : counted.cavityStayed) += stayed;
        (serosa ? counted.serosaVertices : counted.cavityVertices) += static_cast<std::size_t>(l.around);
    }
    // A pole with no crossing of its own follows the ring next to it.
    auto pole = [&](std::size_t v, int ring, const std::vector<std::int32_t>& faces, std::size_t& stayed) {
        if (auto hit = reproject(organ.points[v], normals[v], body,
                                 facesNear({organ.points[v]}, kReprojectReachMm, body, faces), kReprojectReachMm)) {
            onBody.points[v] = *hit;
            return;
        }
        ++stayed;
        const Reader before{organ, l}, after{onBody, l};
        onBody.points[v] = organ.points[v] + (after.centroid(ring) - before.centroid(ring));
    };
    pole(0, 0, serosaFaces, counted.serosaStayed);
    pole(static_cast<std::size_t>(l.innerPole()), l.ringCount() - 1, cavityFaces, counted.cavityStayed);
    ++counted.serosaVertices;
    ++counted.cavityVertices;
    if (crossings)
        *crossings = counted;
    return measureUterus(onBody, l);
}

Result<UterusDimensions> measureUterus(const SurfaceMesh& mesh, const TemplateLayout& l) {
    if (mesh.points.size() != static_cast<std::size_t>(l.vertexCount()) ||
        mesh.triangles.size() != static_cast<std::size_t>(l.faceCount()))
        return fail(ErrorCode::InvalidInput,
                    "mesh has " + std::to_string(mesh.points.size()) + " vertices and " +
                        std::to_string(mesh.triangles.size()) + " triangles; the uterus template has " +
                        std::to_string(l.vertexCount()) + " and " + std::to_string(l.faceCount()));
    const Reader in{mesh, l};
    UterusDimensions d;
    const Vec3 fundus = mesh.points[0];
    const Vec3 cavityFundus = mesh.points[static_cast<std::size_t>(l.innerPole())];
    const Vec3 externalOs = in.centroid(l.firstCanalRing());
    const Vec3 internalOs = in.centroid(l.internalOsRing());

    d.cervixLengthMm = in.centreline(l.firstCanalRing(), l.internalOsRing());
    d.lengthMm = distance(externalOs, in.centroid(l.outerRings - 1)) + in.centreline(l.outerRings - 1, 0) +
                 distance(in.centroid(0), fundus);
    d.corpusLengthMm = d.lengthMm - d.cervixLengthMm;
    d.cavityLengthMm =
        in.centreline(l.internalOsRing(), l.ringCount() - 1) + distance(in.centroid(l.ringCount() - 1), cavityFundus);
    d.fundalWallMm = distance(fundus, cavityFundus);
    for (int r = 0; r < l.outerRings; ++r) {
        d.widthMm = std::max(d.widthMm, in.lateral(r));
        d.apDepthMm = std::max(d.apDepthMm, in.sagittal(r));
    }
    for (int r = l.internalOsRing(); r < l.ringCount(); ++r)
        d.cavityWidthMm = std::max(d.cavityWidthMm, in.lateral(r));
    d.internalOsWidthMm = in.lateral(l.internalOsRing());
    d.cavityAreaCm2 = cavityArea(in) / 100.0;

    // Cervix diameter: the serosa ring closest to the middle of the canal.
    const Vec3 midCanal = in.centroid(l.firstCanalRing() + l.canalRings / 2);
    int best = l.outerRings - 1;
    for (int r = 0; r < l.outerRings; ++r)
        if (distance(in.centroid(r), midCanal) < distance(in.centroid(best), midCanal))
            best = r;
    d.cervixDiameterMm = in.sagittal(best);

    // Flexion: corpus axis (internal os to fundus) against the canal axis, signed towards anterior.
    const Vec3 canalAxis = normalized(internalOs - externalOs);
    const Vec3 corpusAxis = normalized(fundus - internalOs);
    Vec3 anterior = in.at(l.firstCanalRing() + l.canalRings / 2, l.around / 4) -
                    in.at(l.firstCanalRing() + l.canalRings / 2, 3 * l.around / 4);
    anterior = normalized(anterior - canalAxis * dot(anterior, canalAxis));
    const double angle = std::atan2(norm(cross(canalAxis, corpusAxis)), dot(canalAxis, corpusAxis));
    d.flexionDeg = units::radToDeg(dot(corpusAxis, anterior) >= 0.0 ? angle : -angle);

    d.ellipsoidVolumeMl = ellipsoidVolumeMl(d.lengthMm, d.widthMm, d.apDepthMm);
    d.tissueVolumeMl = units::mlFromMm3(enclosedVolume(mesh));
    d.cavityVolumeMl = units::mlFromMm3(cavityVolume(in));
    return d;
}

} // namespace hs::anatomy
