#include "hs/generate/Assembly.h"

#include "hs/anatomy/LibraryVersions.h"
#include "hs/anatomy/UterusGenerator.h"
#include "hs/clinical/Tissue.h"
#include "hs/core/LabelTransfer.h"
#include "hs/core/Subdivision.h"
#include "hs/core/TriangleGeometry.h"
#include "hs/core/Units.h"
#include "hs/generate/Seeds.h"
#include "hs/meshing/BaselineMeshers.h"
#include "hs/meshing/LibraryVersions.h"
#include "hs/texture/LibraryVersions.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <optional>
#include <utility>
#include <variant>

namespace hs::generate {
namespace {

constexpr auto kTissueCervicalCanal = clinical::labelValue(clinical::SurfaceTissue::CervicalCanal);
constexpr auto kTissueOstium = clinical::labelValue(clinical::SurfaceTissue::TubalOstium);

/// The ostia are smaller than the mesh's triangles, so no boundary face may be nearest to an ostium face: carry
/// them the other way too, marking the boundary face nearest to each ostium face of the organ.
Status keepSmallTissueFeatures(const SurfaceMesh& outline, SurfaceMesh& boundary, double reach) {
    SurfaceMesh probe = outline;
    std::vector<std::int32_t> index(boundary.triangles.size());
    for (std::size_t f = 0; f < index.size(); ++f)
        index[f] = static_cast<std::int32_t>(f);
    boundary.faceLabels["faceIndex"] = std::move(index);
    const Status status = transferFaceLabels(boundary, probe, {"faceIndex"}, reach, -1);
    boundary.faceLabels.erase("faceIndex");
    HS_TRY(status);
    const auto& tissue = outline.faceLabels.at(clinical::kSurfaceTissueLabel);
    const auto& nearest = probe.faceLabels.at("faceIndex");
    auto& boundaryTissue = boundary.faceLabels.at(clinical::kSurfaceTissueLabel);
    for (std::size_t f = 0; f < tissue.size(); ++f)
        if (tissue[f] == kTissueOstium && nearest[f] >= 0)
            boundaryTissue[static_cast<std::size_t>(nearest[f])] = kTissueOstium;
    return {};
}

std::string locationKey(const scene::PathologySpec& p) {
    if (const auto* c = std::get_if<clinical::ClinicalPlacement>(&p.placement))
        return std::string(clinical::toString(c->location));
    return "";
}

clinical::Tissue tissueOf(clinical::PathologyKind kind) {
    return kind == clinical::PathologyKind::Myoma ? clinical::Tissue::Myoma : clinical::Tissue::Polyp;
}

} // namespace

std::int32_t pathologyRegion(std::size_t pathologyIndex) {
    return static_cast<std::int32_t>(pathologyIndex) + kCervixRegion + 1;
}

std::vector<scene::SceneRegion> sceneRegions(const scene::CaseSpec& spec, const TetMesh& tets) {
    std::array<bool, 3> present{};
    for (std::size_t t = 0; t < tets.tets.size(); ++t)
        if (const auto r = tets.regionOf(t); isWallRegion(r))
            present[static_cast<std::size_t>(r - kMyometriumRegion)] = true;
    std::vector<scene::SceneRegion> regions;
    const std::array<clinical::Tissue, 3> wall{clinical::Tissue::Myometrium, clinical::Tissue::Endometrium,
                                               clinical::Tissue::Cervix};
    for (std::size_t k = 0; k < wall.size(); ++k)
        if (present[k])
            regions.push_back({kMyometriumRegion + static_cast<std::int32_t>(k),
                               std::string(clinical::toString(wall[k])), wall[k], ""});
    for (std::size_t i = 0; i < spec.pathologies.size(); ++i) {
        const auto& p = spec.pathologies[i];
        regions.push_back({pathologyRegion(i), p.id, tissueOf(p.kind), p.id});
    }
    return regions;
}

TetMesh sceneTets(const TetMesh& meshed, const std::vector<WallLayer>& layers) {
    TetMesh tets = meshed;
    tets.regions.resize(tets.tets.size(), kBodyWallRegion);
    for (std::size_t t = 0; t < tets.tets.size(); ++t) {
        const WallLayer layer = layers.empty() ? WallLayer::Myometrium : layers[t];
        auto& r = tets.regions[t];
        if (layer == WallLayer::Endometrium)
            r = kEndometriumRegion; // the wall's lining, or the cover of a pathology in the cavity
        else if (r == kBodyWallRegion)
            r = layer == WallLayer::Cervix ? kCervixRegion : kMyometriumRegion;
        else
            r = pathologyRegion(static_cast<std::size_t>(r - 1));
    }
    return tets;
}

std::vector<std::int32_t> scopeSeenFaces(const SurfaceMesh& boundary) {
    std::vector<std::int32_t> seen(boundary.triangles.size(), 1);
    const auto tissue = boundary.faceLabels.find(clinical::kSurfaceTissueLabel);
    if (tissue == boundary.faceLabels.end())
        return seen;
    for (std::size_t f = 0; f < seen.size(); ++f)
        seen[f] = tissue->second[f] == clinical::labelValue(clinical::SurfaceTissue::Serosa) ? 0 : 1;
    return seen;
}

int visualSurfaceLevels(const SurfaceMesh& boundary) {
    const SurfaceShape shape = measureSurfaceShape(boundary, scopeSeenFaces(boundary));
    int levels = 0;
    for (double edge = shape.meanEdgeMm; edge > kVisualEdgeLengthMm && levels < kMaxVisualSurfaceLevels; edge /= 2.0)
        ++levels;
    return levels;
}

std::vector<OstiumOpening> ostiumOpenings(const SurfaceMesh& boundary) {
    std::vector<OstiumOpening> out;
    const auto tissue = boundary.faceLabels.find(clinical::kSurfaceTissueLabel);
    if (tissue == boundary.faceLabels.end())
        return out;
    // Union-find over the ostium faces, joined through shared points.
    const std::size_t faces = boundary.triangles.size();
    std::vector<std::int32_t> parent(faces, -1), ownerOfPoint(boundary.points.size(), -1);
    const auto find = [&](std::int32_t f) {
        while (parent[static_cast<std::size_t>(f)] != f)
            f = parent[static_cast<std::size_t>(f)] =
                parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(f)])];
        return f;
    };
    for (std::size_t f = 0; f < faces; ++f) {
        if (tissue->second[f] != kTissueOstium)
            continue;
        parent[f] = static_cast<std::int32_t>(f);
        for (std::int32_t v : boundary.triangles[f]) {
            std::int32_t& owner = ownerOfPoint[static_cast<std::size_t>(v)];
            if (owner < 0) {
                owner = static_cast<std::int32_t>(f);
                continue;
            }
            const std::int32_t a = find(owner), b = find(static_cast<std::int32_t>(f));
            if (a != b)
                parent[static_cast<std::size_t>(std::max(a, b))] = std::min(a, b);
        }
    }
    std::map<std::int32_t, std::pair<Vec3, Vec3>> sums; // root -> (area-weighted centre, area-weighted normal)
    std::map<std::int32_t, double> areas;
    for (std::size_t f = 0; f < faces; ++f) {
        if (parent[f] < 0)
            continue;
        const Triangle& t = boundary.triangles[f];
        const Vec3& a = boundary.points[static_cast<std::size_t>(t[0])];
        const Vec3& b = boundary.points[static_cast<std::size_t>(t[1])];
        const Vec3& c = boundary.points[static_cast<std::size_t>(t[2])];
        const Vec3 n = cross(b - a, c - a); // |n| = 2 area
        const double area = 0.5 * norm(n);
        auto& sum = sums[find(static_cast<std::int32_t>(f))];
        sum.first += (a + b + c) * (area / 3.0);
        sum.second += n;
        areas[find(static_cast<std::int32_t>(f))] += area;
    }
    for (const auto& [root, sum] : sums) {
        const double area = areas.at(root);
        const double len = norm(sum.second);
        if (area <= 0.0 || len <= 0.0)
            continue;
        out.push_back({sum.first / area, sum.second / len});
    }
    return out;
}

std::vector<texture::DarkSpot> ostiumDarkSpots(const std::vector<OstiumOpening>& ostia) {
    std::vector<texture::DarkSpot> spots;
    for (const auto& o : ostia)
        spots.push_back({o.centreMm, 1.5 * kOstiumRadiusMm, 0.85});
    return spots;
}

texture::CloseUpParams closeUpParamsFor(const SurfaceMesh& boundary, const std::vector<OstiumOpening>& ostia) {
    texture::CloseUpParams p;
    for (const auto& o : ostia)
        p.pits.push_back({o.centreMm, o.normal, kOstiumRadiusMm, kOstiumDepthMm});
    p.levels = visualSurfaceLevels(boundary);
    p.seen = scopeSeenFaces(boundary);
    p.smoothing.iterations = 10;
    p.smoothing.maxDisplacement = kMaxVisualFairingMm;
    return p;
}

Result<SurfaceMesh> labelledBoundary(const TetMesh& tets, const SurfaceMesh& outline, const scene::CaseSpec& spec,
                                     double reachMm) {
    SurfaceMesh boundary = extractBoundary(tets);
    HS_TRY(transferFaceLabels(outline, boundary, {clinical::kSurfaceTissueLabel, merge::kPathologyLabel}, reachMm));
    HS_TRY(keepSmallTissueFeatures(outline, boundary, reachMm));
    std::vector<std::int32_t> appearance(boundary.triangles.size(), 0);
    const auto& over = boundary.faceLabels.at(merge::kPathologyLabel);
    for (std::size_t f = 0; f < appearance.size(); ++f) {
        const auto p = over[f] - 1; // 1 + index of the pathology a face is draped over
        if (p >= 0 && static_cast<std::size_t>(p) < spec.pathologies.size())
            appearance[f] =
                spec.pathologies[static_cast<std::size_t>(p)].kind == clinical::PathologyKind::Myoma ? 1 : 2;
    }
    boundary.faceLabels[kAppearanceLabel] = std::move(appearance);
    return boundary;
}

std::vector<std::int32_t> facesWith(const SurfaceMesh& mesh, const std::string& label, std::int32_t value) {
    std::vector<std::int32_t> faces;
    const auto it = mesh.faceLabels.find(label);
    if (it == mesh.faceLabels.end())
        return faces;
    for (std::size_t f = 0; f < it->second.size(); ++f)
        if (it->second[f] == value)
            faces.push_back(static_cast<std::int32_t>(f));
    return faces;
}

namespace {

/// Tets of region `region` that share a face with a tet whose region satisfies `touches`, ascending.
template <class Pred>
std::vector<std::int32_t> tetsTouchingWhere(const TetMesh& mesh,
                                            const std::vector<std::array<std::int32_t, 4>>& adjacent,
                                            std::int32_t region, Pred touches) {
    std::vector<std::int32_t> out;
    for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
        if (mesh.regionOf(t) != region)
            continue;
        for (const auto u : adjacent[t])
            if (u >= 0 && touches(mesh.regionOf(static_cast<std::size_t>(u)))) {
                out.push_back(static_cast<std::int32_t>(t));
                break;
            }
    }
    return out;
}

} // namespace

std::vector<std::int32_t> tetsTouching(const TetMesh& mesh, std::int32_t region, std::int32_t other) {
    return tetsTouchingWhere(mesh, tetNeighbours(mesh), region, [other](std::int32_t r) { return r == other; });
}

std::vector<scene::SceneLabel> sceneLabels(const scene::CaseSpec& spec, const TetMesh& tets,
                                           const SurfaceMesh& visual) {
    std::vector<scene::SceneLabel> labels;
    for (std::size_t i = 0; i < spec.pathologies.size(); ++i) {
        auto faces = facesWith(visual, merge::kPathologyLabel, static_cast<std::int32_t>(i + 1));
        if (!faces.empty())
            labels.push_back({"contact:" + spec.pathologies[i].id, scene::LabelKind::Contact,
                              scene::LabelElement::SurfaceFace, spec.pathologies[i].id, std::move(faces)});
    }
    const auto adjacent = tetNeighbours(tets);
    for (std::size_t i = 0; i < spec.pathologies.size(); ++i) {
        auto base = tetsTouchingWhere(tets, adjacent, pathologyRegion(i), isWallRegion);
        if (!base.empty())
            labels.push_back({"base:" + spec.pathologies[i].id, scene::LabelKind::PathologyBase,
                              scene::LabelElement::Tet, spec.pathologies[i].id, std::move(base)});
    }
    if (auto ostia = facesWith(visual, clinical::kSurfaceTissueLabel, kTissueOstium); !ostia.empty())
        labels.push_back({"ostia", scene::LabelKind::Ostium, scene::LabelElement::SurfaceFace, "", std::move(ostia)});
    if (auto canal = facesWith(visual, clinical::kSurfaceTissueLabel, kTissueCervicalCanal); !canal.empty())
        labels.push_back({"cervical-canal", scene::LabelKind::CervicalCanal, scene::LabelElement::SurfaceFace, "",
                          std::move(canal)});
    return labels;
}

namespace {

bool onCavitySide(std::int32_t tissue) {
    using clinical::SurfaceTissue;
    return tissue == clinical::labelValue(SurfaceTissue::Endometrium) || tissue == kTissueOstium ||
           tissue == kTissueCervicalCanal;
}

/// Faces of `boundary` on one side of the wall (cavity: endometrium, ostia, canal; else serosa, ectocervix), those
/// draped over pathology `draped` (1 + index) only, or over none (0), or all (-1).
std::vector<std::int32_t> sideFaces(const SurfaceMesh& boundary, bool cavity, std::int32_t draped) {
    std::vector<std::int32_t> faces;
    const auto& tissue = boundary.faceLabels.at(clinical::kSurfaceTissueLabel);
    const auto over = boundary.faceLabels.find(merge::kPathologyLabel);
    for (std::size_t f = 0; f < tissue.size(); ++f) {
        const std::int32_t p = over == boundary.faceLabels.end() ? 0 : over->second[f];
        if (onCavitySide(tissue[f]) == cavity && (draped < 0 || p == draped))
            faces.push_back(static_cast<std::int32_t>(f));
    }
    return faces;
}

Vec3 faceNormalArea(const SurfaceMesh& m, std::int32_t f) {
    const auto& t = m.triangles[static_cast<std::size_t>(f)];
    const Vec3& a = m.points[static_cast<std::size_t>(t[0])];
    return cross(m.points[static_cast<std::size_t>(t[1])] - a, m.points[static_cast<std::size_t>(t[2])] - a) * 0.5;
}

/// Where a pathology's cover leaves the wall: the boundary edges of the faces draped over it on one side. Their
/// points are the rim of its base; the plane through them, facing the way the draped faces face, is the wall's
/// surface as it runs beneath the pathology.
struct Rim {
    std::vector<Vec3> points;
    Vec3 centre;
    Vec3 normal; ///< unit, out of the wall (into the cavity, or away from the serosa)
    double radius = 0.0;
};

std::optional<Rim> rimOf(const SurfaceMesh& boundary, const std::vector<std::int32_t>& patch) {
    if (patch.empty())
        return std::nullopt;
    std::map<std::pair<std::int32_t, std::int32_t>, int> edges;
    Vec3 normal;
    for (const auto f : patch) {
        const auto& t = boundary.triangles[static_cast<std::size_t>(f)];
        for (std::size_t e = 0; e < 3; ++e)
            ++edges[std::minmax(t[e], t[(e + 1) % 3])];
        normal += faceNormalArea(boundary, f);
    }
    std::vector<std::int32_t> ids;
    for (const auto& [edge, count] : edges)
        if (count == 1) {
            ids.push_back(edge.first);
            ids.push_back(edge.second);
        }
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
    if (ids.empty() || norm(normal) <= 0.0)
        return std::nullopt;
    Rim rim;
    for (const auto v : ids)
        rim.points.push_back(boundary.points[static_cast<std::size_t>(v)]);
    for (const Vec3& p : rim.points)
        rim.centre += p;
    rim.centre = rim.centre / static_cast<double>(rim.points.size());
    rim.normal = normalized(normal);
    for (const Vec3& p : rim.points) {
        const Vec3 d = p - rim.centre;
        rim.radius = std::max(rim.radius, norm(d - rim.normal * dot(d, rim.normal)));
    }
    return rim;
}

/// Whether `p` lies beyond the rim's plane and within its footprint (the part that stands out of the wall).
bool beyond(const Rim& rim, const Vec3& p) {
    const Vec3 d = p - rim.centre;
    const double h = dot(d, rim.normal);
    return h > 0.0 && norm(d - rim.normal * h) <= rim.radius + h;
}

/// Smallest distance from `points` to `faces` of `mesh`, faces farther than `cutoff` from the points' box ignored.
double distanceTo(const std::vector<Vec3>& points, const SurfaceMesh& mesh, const std::vector<std::int32_t>& faces,
                  double cutoff) {
    Vec3 lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
    for (const Vec3& p : points) {
        lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
        hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
    }
    double best2 = cutoff * cutoff;
    for (const auto f : faces) {
        const auto& t = mesh.triangles[static_cast<std::size_t>(f)];
        const Vec3& a = mesh.points[static_cast<std::size_t>(t[0])];
        if (a.x < lo.x - cutoff || a.y < lo.y - cutoff || a.z < lo.z - cutoff || a.x > hi.x + cutoff ||
            a.y > hi.y + cutoff || a.z > hi.z + cutoff)
            continue;
        const Vec3& b = mesh.points[static_cast<std::size_t>(t[1])];
        const Vec3& c = mesh.points[static_cast<std::size_t>(t[2])];
        for (const Vec3& p : points)
            best2 = std::min(best2, closestPointOnTriangle(p, a, b, c).distance2);
    }
    return std::sqrt(best2);
}

double largestDiameter(const std::vector<Vec3>& points) {
    double d2 = 0.0;
    for (std::size_t i = 0; i < points.size(); ++i)
        for (std::size_t j = i + 1; j < points.size(); ++j)
            d2 = std::max(d2, norm2(points[i] - points[j]));
    return std::sqrt(d2);
}

/// Barycentric sample points of a tet (its centroid and one point towards each corner), equal weights: enough to
/// split a 2 mm tet by a plane to a few per cent of its volume.
constexpr std::array<std::array<double, 4>, 5> kTetSamples{{{0.25, 0.25, 0.25, 0.25},
                                                            {0.55, 0.15, 0.15, 0.15},
                                                            {0.15, 0.55, 0.15, 0.15},
                                                            {0.15, 0.15, 0.55, 0.15},
                                                            {0.15, 0.15, 0.15, 0.55}}};

/// A pathology region of the tets: its volume, volume centroid, the volumes beyond the rims of what is draped over
/// it (in the cavity, outside the serosa) and the points of its surface.
struct RegionShape {
    double volume = 0.0;   ///< mm^3
    double inCavity = 0.0; ///< mm^3
    double outside = 0.0;  ///< mm^3
    Vec3 centre;
    std::vector<Vec3> surface;
};

RegionShape regionShape(const TetMesh& tets, const std::vector<std::array<std::int32_t, 4>>& adjacent,
                        std::int32_t region, const std::optional<Rim>& cavityRim, const std::optional<Rim>& serosaRim) {
    RegionShape r;
    std::vector<std::uint8_t> onSurface(tets.points.size(), 0);
    Vec3 moment;
    for (std::size_t t = 0; t < tets.tets.size(); ++t) {
        if (tets.regionOf(t) != region)
            continue;
        const auto& tet = tets.tets[t];
        std::array<Vec3, 4> p;
        for (std::size_t k = 0; k < 4; ++k)
            p[k] = tets.points[static_cast<std::size_t>(tet[k])];
        const double v = std::abs(dot(p[1] - p[0], cross(p[2] - p[0], p[3] - p[0]))) / 6.0;
        r.volume += v;
        moment += (p[0] + p[1] + p[2] + p[3]) * (0.25 * v);
        for (const auto& w : kTetSamples) {
            const Vec3 q = p[0] * w[0] + p[1] * w[1] + p[2] * w[2] + p[3] * w[3];
            if (cavityRim && beyond(*cavityRim, q))
                r.inCavity += v / kTetSamples.size();
            else if (serosaRim && beyond(*serosaRim, q))
                r.outside += v / kTetSamples.size();
        }
        for (std::size_t k = 0; k < 4; ++k) {
            const auto u = adjacent[t][k];
            if (u >= 0 && tets.regionOf(static_cast<std::size_t>(u)) == region)
                continue;
            for (const int corner : kTetFacePoints[k])
                onSurface[static_cast<std::size_t>(tet[static_cast<std::size_t>(corner)])] = 1;
        }
    }
    for (std::size_t v = 0; v < onSurface.size(); ++v)
        if (onSurface[v])
            r.surface.push_back(tets.points[v]);
    r.centre = r.volume > 0.0 ? moment / r.volume : Vec3{};
    return r;
}

/// Pathology region `region` (pathology `index`) of `tets` against the scene's boundary, as a
/// pathology::WallContact.
pathology::WallContact contactOf(const TetMesh& tets, const std::vector<std::array<std::int32_t, 4>>& adjacent,
                                 std::int32_t region, std::size_t index, const SurfaceMesh& boundary,
                                 const std::vector<std::int32_t>& cavityFaces,
                                 const std::vector<std::int32_t>& serosaFaces) {
    const auto draped = static_cast<std::int32_t>(index + 1);
    const auto cavityRim = rimOf(boundary, sideFaces(boundary, true, draped));
    const auto serosaRim = rimOf(boundary, sideFaces(boundary, false, draped));
    RegionShape shape = regionShape(tets, adjacent, region, cavityRim, serosaRim);
    const double volume = shape.volume, inCavity = shape.inCavity, outside = shape.outside;
    pathology::WallContact c;
    c.points = std::move(shape.surface);
    c.volumeMm3 = volume;
    c.centre = shape.centre;
    c.sizeMm = largestDiameter(c.points);
    auto& f = c.fractions;
    if (volume > 0.0) {
        f.cavity = inCavity / volume;
        f.outside = outside / volume;
    }
    f.tissue = std::max(0.0, 1.0 - f.cavity - f.outside);
    constexpr double kReachMm = 30.0; // as far as the pathology stage looks for the surfaces
    f.endometriumDistanceMm = f.cavity > 0.0 ? 0.0 : distanceTo(c.points, boundary, cavityFaces, kReachMm);
    f.serosaDistanceMm = f.outside > 0.0 ? 0.0 : distanceTo(c.points, boundary, serosaFaces, kReachMm);
    // The base lies on the side it stands out of, else on the nearer surface (as the pathology stage chooses it).
    c.serosalBase = !(f.cavity > 0.0 || (f.outside == 0.0 && f.endometriumDistanceMm <= f.serosaDistanceMm));
    const auto& rim = c.serosalBase ? serosaRim : cavityRim;
    if (rim)
        c.base = rim->points;
    return c;
}

} // namespace

MeasuredDescriptors clinicalDescriptors(const scene::CaseSpec& spec, const SurfaceMesh& organ,
                                        const anatomy::TemplateLayout& layout, const TetMesh& tets,
                                        const SurfaceMesh& boundary, const std::vector<Vec3>& roots) {
    MeasuredDescriptors out;
    auto& c = out.clinical;
    const auto cavityFaces = sideFaces(boundary, true, -1);
    const auto serosaFaces = sideFaces(boundary, false, -1);
    // The cavity's own wall: not what is draped over a pathology standing in it (beneath one, the displaced
    // organ's wall counts).
    anatomy::BodyCrossings crossings;
    if (auto body =
            anatomy::measureBody(organ, layout, boundary, serosaFaces, sideFaces(boundary, true, 0), &crossings)) {
        // Where nothing of the body lies along a vertex's normal the displaced organ's position is kept: say how often.
        if (crossings.serosaStayed + crossings.cavityStayed > 0) {
            char text[320];
            std::snprintf(text, sizeof text,
                          "organ: %zu of %zu serosa and %zu of %zu cavity vertices of the template found no body "
                          "surface within 20 mm along their normal and were measured where the displaced organ has "
                          "them (beneath a pathology standing in the cavity, the wall it covers)",
                          crossings.serosaStayed, crossings.serosaVertices, crossings.cavityStayed,
                          crossings.cavityVertices);
            out.measurementWarnings.push_back(text);
        }
        c.organ = {body->lengthMm,       body->widthMm,       body->apDepthMm,
                   body->cavityLengthMm, body->cavityWidthMm, body->ellipsoidVolumeMl};
    } else {
        out.warnings.push_back("the organ's dimensions were not measured: " + body.error().detail);
    }
    const auto adjacent = tetNeighbours(tets);
    const double tolerance = pathologyParamsFor(spec).contactToleranceMm;
    for (std::size_t i = 0; i < spec.pathologies.size(); ++i) {
        const auto& asked = spec.pathologies[i];
        scene::PathologyDescriptor pd;
        pd.id = asked.id;
        pd.kind = asked.kind;
        pd.regionId = pathologyRegion(i);
        pd.location = locationKey(asked);
        auto contact = contactOf(tets, adjacent, pd.regionId, i, boundary, cavityFaces, serosaFaces);
        if (i < roots.size())
            contact.root = roots[i];
        pd.volumeMl = units::mlFromMm3(contact.volumeMm3);
        pd.sizeMm = contact.sizeMm;
        if (contact.volumeMm3 <= 0.0) {
            out.warnings.push_back(asked.id + ": no tets in its region; not measured");
        } else if (auto d = pathology::describeContact(boundary, contact, asked.kind, tolerance)) {
            pd.sizeMm = d->sizeMm;
            if (asked.kind == clinical::PathologyKind::Myoma) {
                pd.figo = d->figo;
                pd.lasmar = d->lasmar;
            }
        } else {
            out.warnings.push_back(asked.id + ": FIGO and Lasmar not measured: " + d.error().detail);
        }
        c.pathologies.push_back(pd);
    }
    auto differ = descriptorWarnings(spec, c);
    out.warnings.insert(out.warnings.end(), differ.begin(), differ.end());
    return out;
}

namespace {

std::string mm(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.1f", v);
    return buf;
}

/// A measured length against an asked one: empty when within kDescriptorTolerance.
std::string lengthDiffers(const std::string& what, std::optional<double> asked, double measured) {
    if (!asked || *asked <= 0.0 || std::abs(measured - *asked) <= kDescriptorTolerance * *asked)
        return "";
    return "asked " + what + " " + mm(*asked) + " mm, the final body measures " + mm(measured) + " mm";
}

} // namespace

std::vector<std::string> descriptorWarnings(const scene::CaseSpec& spec, const scene::ClinicalDescriptors& measured) {
    std::vector<std::string> out;
    const auto& asked = spec.anatomy.dimensions;
    const auto& o = measured.organ;
    for (auto& w : {lengthDiffers("length", asked.lengthMm, o.lengthMm),
                    lengthDiffers("width", asked.widthMm, o.widthMm), lengthDiffers("AP depth", asked.apMm, o.apMm),
                    lengthDiffers("cavity length", asked.cavityLengthMm, o.cavityLengthMm),
                    lengthDiffers("cavity width", asked.cavityWidthMm, o.cavityWidthMm)})
        if (!w.empty())
            out.push_back("organ: " + w);
    for (std::size_t i = 0; i < spec.pathologies.size() && i < measured.pathologies.size(); ++i) {
        const auto& a = spec.pathologies[i];
        const auto& m = measured.pathologies[i];
        if (auto w = lengthDiffers("size", a.sizeMm, m.sizeMm); !w.empty())
            out.push_back(a.id + ": " + w);
        if (a.figo && m.figo && *a.figo != *m.figo)
            out.push_back(a.id + ": asked FIGO " + a.figo->toString() + ", the final body measures FIGO " +
                          m.figo->toString());
    }
    return out;
}

std::string descriptorTable(const scene::CaseSpec& spec, const scene::ClinicalDescriptors& measured) {
    std::string t = "value                      asked     measured\n";
    auto row = [&t](const std::string& what, const std::string& asked, const std::string& got) {
        char buf[160];
        std::snprintf(buf, sizeof buf, "%-26s %-9s %s\n", what.c_str(), asked.c_str(), got.c_str());
        t += buf;
    };
    auto opt = [](std::optional<double> v) { return v ? mm(*v) : std::string("-"); };
    const auto& a = spec.anatomy.dimensions;
    const auto& o = measured.organ;
    row("organ length mm", opt(a.lengthMm), mm(o.lengthMm));
    row("organ width mm", opt(a.widthMm), mm(o.widthMm));
    row("organ AP mm", opt(a.apMm), mm(o.apMm));
    row("cavity length mm", opt(a.cavityLengthMm), mm(o.cavityLengthMm));
    row("cavity width mm", opt(a.cavityWidthMm), mm(o.cavityWidthMm));
    row("uterine volume mL", "-", mm(o.uterineVolumeMl));
    for (std::size_t i = 0; i < spec.pathologies.size() && i < measured.pathologies.size(); ++i) {
        const auto& p = spec.pathologies[i];
        const auto& m = measured.pathologies[i];
        row(p.id + " size mm", mm(p.sizeMm), mm(m.sizeMm));
        row(p.id + " volume mL", "-", mm(m.volumeMl));
        if (p.kind == clinical::PathologyKind::Myoma) {
            row(p.id + " FIGO", p.figo ? p.figo->toString() : "-", m.figo ? m.figo->toString() : "-");
            if (m.lasmar)
                row(p.id + " Lasmar S/T/E/P/W", "-",
                    std::to_string(m.lasmar->size) + "/" + std::to_string(m.lasmar->topography) + "/" +
                        std::to_string(m.lasmar->extension) + "/" + std::to_string(m.lasmar->penetration) + "/" +
                        std::to_string(m.lasmar->wall) + " = " + std::to_string(m.lasmar->total()));
        }
    }
    return t;
}

scene::SceneLabel supportLabel(const TetMesh& tets, double cervixLengthMm) {
    scene::SceneLabel label;
    label.name = scene::kSupportLabel;
    label.kind = scene::LabelKind::Other;
    label.element = scene::LabelElement::Tet;
    const double reach2 = cervixLengthMm * cervixLengthMm;
    for (std::size_t t = 0; t < tets.tetCount(); ++t) {
        const auto& tet = tets.tets[t];
        if (std::all_of(tet.begin(), tet.end(), [&](std::int32_t v) {
                const Vec3& p = tets.points[static_cast<std::size_t>(v)];
                return p.x * p.x + p.y * p.y + p.z * p.z <= reach2;
            }))
            label.indices.push_back(static_cast<std::int32_t>(t));
    }
    return label;
}

LibraryVersions toolVersionsFor(const scene::CaseSpec& spec) {
    LibraryVersions versions = scene::defaultToolVersions();
    versions.merge(anatomy::libraryVersions());
    versions.merge(meshing::libraryVersions());
    versions.merge(meshing::methodLibraryVersions(meshMethodFor(spec)));
    versions.merge(texture::libraryVersions());
    return versions;
}

scene::MeshQuality qualityOf(const meshing::QualityReport& q) {
    scene::MeshQuality m;
    m.vertexCount = q.vertexCount;
    m.tetCount = q.tetCount;
    m.meanRadiusRatio = q.meanRadiusRatio;
    m.minRadiusRatio = q.minRadiusRatio;
    m.minDihedralDeg = q.minDihedralDeg;
    m.maxDihedralDeg = q.maxDihedralDeg;
    m.meanEdgeRatio = q.meanEdgeRatio;
    m.maxEdgeRatio = q.maxEdgeRatio;
    m.radiusRatioHistogram.assign(q.radiusRatioHistogram.begin(), q.radiusRatioHistogram.end());
    m.minDihedralHistogram.assign(q.minDihedralHistogram.begin(), q.minDihedralHistogram.end());
    m.sliverCount = q.sliverCount;
    m.invertedCount = q.invertedCount;
    m.degenerateCount = q.degenerateCount;
    m.hasReference = q.hasReference;
    m.hausdorffDistanceMm = q.hausdorffDistance;
    m.hausdorffRelative = q.hausdorffRelative;
    m.volumeError = q.volumeError;
    return m;
}

Result<TissueStage> tissueStage(const scene::CaseSpec& spec, const merge::MergeResult& merged,
                                const meshing::MeshResult& meshed, const TissueLayerParams& params) {
    const double reach = 3.0 * std::max(meshed.targetEdgeLength, 0.5);
    auto boundary = labelledBoundary(meshed.mesh, merged.body.surfaces.front().surface, spec, reach);
    if (!boundary)
        return boundary.failure();
    TissueStage out;
    out.layers = tissueLayers(meshed.mesh, kBodyWallRegion, *boundary, params);
    out.tets = sceneTets(meshed.mesh, out.layers.layer);
    out.regions = sceneRegions(spec, out.tets);
    // The boundary's faces do not depend on the region ids (no interfaces): take the scene's ids from the same
    // extraction of the relabelled mesh.
    out.boundary = std::move(boundary).value();
    out.boundary.faceLabels["region"] = extractBoundary(out.tets).faceLabels.at("region");
    return out;
}

Result<scene::Scene> assembleScene(const scene::CaseSpec& spec, const OrganInstance& organ,
                                   const pathology::PathologyResult& grown, const merge::MergeResult& merged,
                                   const meshing::MeshResult& meshed, const TissueStage& tissue,
                                   const Appearance& appearance) {
    scene::Scene s;
    s.tets = tissue.tets;
    s.regions = tissue.regions;
    s.surface = appearance.surface;

    scene::MaterialOptions materialOptions;
    materialOptions.seed = streamSeed(spec.seed, Stream::Material);
    auto materials = scene::assignMaterials(s.tets, s.regions, spec.scene, materialOptions);
    if (!materials)
        return materials.failure();
    s.materials = std::move(materials).value();

    s.labels = sceneLabels(spec, s.tets, s.surface.mesh);
    s.labels.push_back(supportLabel(s.tets, organ.dimensions.cervixLengthMm));
    // The displaced organ is the template instance nearest to the final body (the same frame, its rings moved where
    // the pathologies pushed them); without pathologies it is the organ itself.
    const SurfaceMesh& frame = grown.organ.points.size() == organ.mesh.points.size() ? grown.organ : organ.mesh;
    std::vector<Vec3> roots;
    for (const auto& p : grown.pathologies)
        roots.push_back(p.anchor);
    if (roots.size() != spec.pathologies.size())
        roots.clear();
    auto descriptors = clinicalDescriptors(spec, frame, organ.layout, tissue.tets, tissue.boundary, roots);
    s.clinical = std::move(descriptors.clinical);
    // The fitted hydrometra of the final body (its measured uterine volume, pathologies included); the organ's own
    // only when the body could not be measured, and then said (clinicalDescriptors warns why).
    double uterineVolumeMl = s.clinical.organ.uterineVolumeMl;
    std::string hydrometraWarning;
    if (!(uterineVolumeMl > 0.0)) {
        uterineVolumeMl = organ.dimensions.ellipsoidVolumeMl;
        char text[160];
        std::snprintf(text, sizeof text,
                      "hydrometra: from the organ before its pathologies (%.1f mL): the final body's volume was not "
                      "measured",
                      uterineVolumeMl);
        hydrometraWarning = text;
    }
    auto hydrometra = scene::computeHydrometra(uterineVolumeMl, spec.scene.hydrometraPressureKpa);
    if (!hydrometra)
        return hydrometra.failure();
    s.hydrometra = *hydrometra;
    s.quality = qualityOf(meshed.quality);
    s.caseSpec = spec;
    s.toolVersions = toolVersionsFor(spec);
    for (const auto& w : appearance.warnings)
        s.warnings.push_back("texture: " + w);
    for (const auto& w : grown.warnings)
        s.warnings.push_back("pathology: " + w);
    for (const auto& w : merged.warnings)
        s.warnings.push_back("merge: " + w);
    for (const auto& w : meshed.warnings)
        s.warnings.push_back("meshing: " + w);
    for (const auto& w : descriptors.warnings)
        s.warnings.push_back("descriptors: " + w);
    for (const auto& w : descriptors.measurementWarnings)
        s.warnings.push_back("measurement: " + w);
    if (!hydrometraWarning.empty())
        s.warnings.push_back(hydrometraWarning);
    HS_TRY(scene::checkScene(s));
    return s;
}

} // namespace hs::generate
