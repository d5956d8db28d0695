#include "hs/anatomy/UterusGenerator.h"

#include "hs/core/Units.h"

#include <algorithm>
#include <cmath>

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

} // namespace

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

    d.ellipsoidVolumeMl = units::mlFromMm3(d.lengthMm * d.widthMm * d.apDepthMm * kEllipsoidFactor);
    d.tissueVolumeMl = units::mlFromMm3(enclosedVolume(mesh));
    d.cavityVolumeMl = units::mlFromMm3(cavityVolume(in));
    return d;
}

} // namespace hs::anatomy
