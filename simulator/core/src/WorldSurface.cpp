// The contact surface's faces: which face the cavity, the zones of the exploration, the ostia, the pathologies.
#include "WorldImpl.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace hs::sim {

namespace detail {

Vec3 triangleNormal(const std::vector<Vec3>& pts, const Triangle& t) {
    return cross(pts[static_cast<std::size_t>(t[1])] - pts[static_cast<std::size_t>(t[0])],
                 pts[static_cast<std::size_t>(t[2])] - pts[static_cast<std::size_t>(t[0])]);
}

Vec3 triangleCentre(const std::vector<Vec3>& pts, const Triangle& t) {
    return (pts[static_cast<std::size_t>(t[0])] + pts[static_cast<std::size_t>(t[1])] +
            pts[static_cast<std::size_t>(t[2])]) /
           3.0;
}

} // namespace detail

using namespace detail;

Vec3 World::Impl::faceNormal(std::int32_t f) const {
    return normalized(triangleNormal(pointsMm, (*triangles)[static_cast<std::size_t>(f)]));
}

Vec3 World::Impl::faceCentre(std::int32_t f) const {
    return triangleCentre(pointsMm, (*triangles)[static_cast<std::size_t>(f)]);
}

void World::Impl::setupSurfaceData() {
    // The contact surface: the simulation mesh's boundary, in the mesh's own point indices (the tissue model's).
    auto tris = std::make_shared<std::vector<Triangle>>(uterus.boundary);
    triangles = tris;
    contactSurface.points = simRest.points;
    contactSurface.triangles = *tris;
    const std::size_t faces = tris->size();
    faceCavity = uterus.faceCavity;
    faceInCavity.assign(faces, 0);
    faceArea.assign(faces, 0.0);
    faceRegion = uterus.region;
    facePathology.assign(faces, -1);
    faceUnrolled.assign(faces, {});
    faceTet = uterus.faceTet;
    faceDead.assign(faces, 0);
    faceCut.assign(faces, 0);
    faceSealed.assign(faces, 0);
    cavityAxis = normalized(landmarks.fundusMm - landmarks.internalOsMm);
    cavityAnterior = perpendicularTo(cavityAxis, frame.anterior);
    cavityLeft = cross(cavityAxis, cavityAnterior);
    if (dot(cavityLeft, frame.left) < 0.0)
        cavityLeft = cavityLeft * -1.0;
    Zone fundus{"fundus", {}, 0.0}, anterior{"anterior", {}, 0.0}, posterior{"posterior", {}, 0.0},
        left{"left", {}, 0.0}, right{"right", {}, 0.0};
    std::vector<std::int32_t> cavityFaceIds;
    std::vector<std::int32_t> cavitySide(faces, 0);
    for (std::size_t f = 0; f < faces; ++f) {
        const Triangle& t = (*tris)[f];
        const bool cavity = faceCavity[f] != 0;
        const Vec3 n = triangleNormal(simRest.points, t);
        faceArea[f] = 0.5 * norm(n);
        const Vec3 c = triangleCentre(simRest.points, t);
        const double along = dot(c - landmarks.internalOsMm, cavityAxis);
        const Vec3 r = c - landmarks.internalOsMm - cavityAxis * along;
        faceUnrolled[f].alongMm = along;
        faceUnrolled[f].aroundDeg = std::atan2(dot(r, cavityLeft), dot(r, cavityAnterior)) / kDeg;
        if (!cavity || dot(c - landmarks.internalOsMm, frame.axis) < 2.0)
            continue;
        faceInCavity[f] = 1;
        const auto fi = static_cast<std::int32_t>(f);
        cavityFaceIds.push_back(fi);
        cavityArea += faceArea[f];
        const Vec3 unit = normalized(n);
        if (distance(c, landmarks.fundusMm) < kFundusZoneMm)
            fundus.faces.push_back(fi);
        const double a = dot(unit, cavityAnterior), l = dot(unit, cavityLeft);
        if (a < -0.5)
            anterior.faces.push_back(fi); // the tissue lies anterior: the anterior wall
        if (a > 0.5)
            posterior.faces.push_back(fi);
        if (l < -0.5)
            left.faces.push_back(fi);
        if (l > 0.5)
            right.faces.push_back(fi);
    }
    for (Zone* z : {&fundus, &anterior, &posterior, &left, &right}) {
        for (const std::int32_t f : z->faces)
            z->area += faceArea[static_cast<std::size_t>(f)];
        zones.push_back(std::move(*z));
    }

    // Ostia: the visual surface's ostium faces, one or two clusters (a pathology may cover an ostium: the scene then
    // has one), each named by its side and its centre bound to the simulation mesh.
    const auto& visual = scene.surface.mesh;
    std::vector<Vec3> ostiumCentres, ostiumNormals;
    std::map<std::string, std::vector<Vec3>> contact;
    for (const auto& label : scene.labels) {
        if (label.element != scene::LabelElement::SurfaceFace)
            continue;
        for (const std::int32_t f : label.indices) {
            if (f < 0 || static_cast<std::size_t>(f) >= visual.faceCount())
                continue;
            const Triangle& vt = visual.triangles[static_cast<std::size_t>(f)];
            const Vec3 c = triangleCentre(visual.points, vt);
            if (label.kind == scene::LabelKind::Ostium) {
                ostiumCentres.push_back(c);
                ostiumNormals.push_back(triangleNormal(visual.points, vt));
            } else if (label.kind == scene::LabelKind::Contact && !label.pathologyId.empty()) {
                contact[label.pathologyId].push_back(c);
            }
        }
    }
    if (!ostiumCentres.empty()) {
        // Two clusters split at the middle of the faces' spread across the cavity, one when they lie together.
        double lo = 1e300, hi = -1e300;
        for (const Vec3& c : ostiumCentres) {
            lo = std::min(lo, dot(c - landmarks.internalOsMm, cavityLeft));
            hi = std::max(hi, dot(c - landmarks.internalOsMm, cavityLeft));
        }
        const bool two = hi - lo > kOstiumSeparationMm;
        Vec3 sums[2] = {{0, 0, 0}, {0, 0, 0}}, normals[2] = {{0, 0, 0}, {0, 0, 0}};
        double counts[2] = {0.0, 0.0};
        for (std::size_t i = 0; i < ostiumCentres.size(); ++i) {
            const int k = two && dot(ostiumCentres[i] - landmarks.internalOsMm, cavityLeft) < 0.5 * (lo + hi) ? 1 : 0;
            sums[k] = sums[k] + ostiumCentres[i];
            normals[k] = normals[k] + ostiumNormals[i];
            counts[k] += 1.0;
        }
        for (int k = 0; k < 2; ++k) {
            if (counts[k] == 0.0 || norm(normals[k]) < 1e-12)
                continue;
            const Vec3 centre = sums[k] / counts[k];
            Ostium o;
            // The patient's side as the canal's frame has it: with one ostium found the fundus landmark is that
            // ostium's cornu, so the cavity's axis points at it and cannot tell its side.
            o.name = dot(centre - landmarks.internalOsMm, frame.left) >= 0.0 ? "ostium-left" : "ostium-right";
            o.at = embedPoints(simRest, {centre}).front();
            o.normal = normalized(normals[k]);
            if (o.at.tet >= 0)
                ostia.push_back(o);
        }
        std::sort(ostia.begin(), ostia.end(), [](const Ostium& a, const Ostium& b) { return a.name < b.name; });
    }
    // Pathologies: the cavity faces near the visual faces over each.
    for (std::size_t p = 0; p < scene.clinical.pathologies.size(); ++p) {
        const auto it = contact.find(scene.clinical.pathologies[p].id);
        if (it == contact.end())
            continue;
        for (const std::int32_t f : cavityFaceIds) {
            const Vec3 c = triangleCentre(simRest.points, (*tris)[static_cast<std::size_t>(f)]);
            for (const Vec3& q : it->second)
                if (distance(c, q) < kPathologyReachMm) {
                    facePathology[static_cast<std::size_t>(f)] = static_cast<int>(p);
                    break;
                }
        }
    }
    faceSeen.assign(faces, 0);

    for (const Ostium& o : ostia)
        metrics.targets.push_back({o.name, 0.0, false, -1.0});
    for (std::size_t i = 0; i < ostia.size(); ++i)
        ostia[i].target = static_cast<int>(i);
    for (const Zone& z : zones)
        metrics.targets.push_back({z.name, 0.0, false, -1.0});
    for (const auto& p : scene.clinical.pathologies)
        metrics.pathologies.push_back({p.id, std::string(clinical::toString(p.kind)), false, false, -1.0});
}

bool World::Impl::insideRestHull(const Vec3& p) const {
    // Ray parity against the serosa at rest (the cavity's faces close the hull at the os only): odd inside.
    int crossings = 0;
    for (std::size_t f = 0; f < triangles->size(); ++f) {
        if (faceCavity[f])
            continue;
        const Triangle& t = (*triangles)[f];
        double th = 0.0, u = 0.0, v = 0.0;
        if (hs::rayTriangle(p, cavityAxis, simRest.points[static_cast<std::size_t>(t[0])],
                            simRest.points[static_cast<std::size_t>(t[1])],
                            simRest.points[static_cast<std::size_t>(t[2])], 0.0, th, u, v))
            ++crossings;
    }
    return crossings % 2 == 1;
}

Vec3 World::Impl::ostiumPoint(const Ostium& o) const {
    const Tet& t = simRest.tets[static_cast<std::size_t>(o.at.tet)];
    Vec3 p{0.0, 0.0, 0.0};
    for (std::size_t k = 0; k < 4; ++k)
        p = p + pointsMm[static_cast<std::size_t>(t[k])] * o.at.weights[k];
    return p;
}

} // namespace hs::sim
