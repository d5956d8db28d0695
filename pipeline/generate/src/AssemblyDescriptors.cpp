// The clinical descriptors measured on the final scene (organ dimensions, each pathology's size, volume, FIGO type
// and Lasmar score) and how they compare with what the case asked.
#include "hs/generate/Assembly.h"

#include "AssemblySteps.h"
#include "hs/anatomy/UterusGenerator.h"
#include "hs/clinical/Tissue.h"
#include "hs/core/TriangleGeometry.h"
#include "hs/core/Units.h"

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

using detail::kTissueCervicalCanal;
using detail::kTissueOstium;

std::string locationKey(const scene::PathologySpec& p) {
    if (const auto* c = std::get_if<clinical::ClinicalPlacement>(&p.placement))
        return std::string(clinical::toString(c->location));
    return "";
}

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
    bool bordersEndometrium = false; ///< a face of it is shared with a tet of the endometrium's region
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
            if (u >= 0 && tets.regionOf(static_cast<std::size_t>(u)) == kEndometriumRegion)
                r.bordersEndometrium = true;
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
    // FIGO 3 against 4 by the layer as the tets have it (laid after placement), not by a distance to the cavity.
    f.bordersEndometrium = shape.bordersEndometrium;
    // The base lies on the side it stands out of, else on the nearer surface (as the pathology stage chooses it).
    c.serosalBase = !(f.cavity > 0.0 || (f.outside == 0.0 && f.endometriumDistanceMm <= f.serosaDistanceMm));
    const auto& rim = c.serosalBase ? serosaRim : cavityRim;
    if (rim)
        c.base = rim->points;
    return c;
}

/// Share of region `region`'s surface (by area) against tissue: a face of it lies in the cavity when the ray from
/// its centre along its outward normal first meets the body's boundary on the cavity side within `reachMm` (through
/// no more than the endometrium laid over it); any other face lies against tissue (the base or stalk of a polyp).
double tissueContactFraction(const TetMesh& tets, const std::vector<std::array<std::int32_t, 4>>& adjacent,
                             std::int32_t region, const SurfaceMesh& boundary, double reachMm) {
    struct Face {
        Vec3 centre, normal;
        double area = 0.0;
    };
    std::vector<Face> faces;
    Bounds box;
    for (std::size_t t = 0; t < tets.tets.size(); ++t) {
        if (tets.regionOf(t) != region)
            continue;
        for (std::size_t k = 0; k < 4; ++k) {
            const auto u = adjacent[t][k];
            if (u >= 0 && tets.regionOf(static_cast<std::size_t>(u)) == region)
                continue;
            std::array<Vec3, 3> p;
            for (std::size_t c = 0; c < 3; ++c)
                p[c] =
                    tets.points[static_cast<std::size_t>(tets.tets[t][static_cast<std::size_t>(kTetFacePoints[k][c])])];
            Vec3 n = cross(p[1] - p[0], p[2] - p[0]);
            const double twice = norm(n);
            if (!(twice > 0.0))
                continue;
            if (signedVolume(tets, t) < 0.0)
                n = -n; // kTetFacePoints wind outward for a positive tet
            faces.push_back({(p[0] + p[1] + p[2]) / 3.0, n / twice, 0.5 * twice});
            box.add(faces.back().centre);
        }
    }
    // The boundary faces a ray of length reachMm from the region can meet.
    const auto& tissue = boundary.faceLabels.at(clinical::kSurfaceTissueLabel);
    std::vector<std::int32_t> near;
    for (std::size_t f = 0; f < boundary.triangles.size(); ++f) {
        Bounds fb;
        for (auto v : boundary.triangles[f])
            fb.add(boundary.points[static_cast<std::size_t>(v)]);
        bool overlaps = true;
        for (int q = 0; q < 3; ++q)
            overlaps = overlaps && fb.max[q] >= box.min[q] - reachMm && fb.min[q] <= box.max[q] + reachMm;
        if (overlaps)
            near.push_back(static_cast<std::int32_t>(f));
    }
    double total = 0.0, against = 0.0;
    for (const Face& face : faces) {
        total += face.area;
        double first = reachMm;
        bool cavity = false;
        for (auto f : near) {
            const auto& tri = boundary.triangles[static_cast<std::size_t>(f)];
            double t = 0.0, u = 0.0, v = 0.0;
            if (rayTriangle(face.centre, face.normal, boundary.points[static_cast<std::size_t>(tri[0])],
                            boundary.points[static_cast<std::size_t>(tri[1])],
                            boundary.points[static_cast<std::size_t>(tri[2])], 1e-9, t, u, v) &&
                t <= first) {
                first = t;
                cavity = onCavitySide(tissue[static_cast<std::size_t>(f)]);
            }
        }
        if (!cavity)
            against += face.area;
    }
    return total > 0.0 ? against / total : 0.0;
}

/// A polyp whose surface lies against tissue beyond its attachment's bar, as a warning; empty when it stands.
std::string seatingWarning(const scene::PathologySpec& a, const scene::PathologyDescriptor& m) {
    if (!a.attachment || !m.tissueContactFraction)
        return "";
    const bool stalked = *a.attachment == clinical::PolypAttachment::Pedunculated;
    const double bar = stalked ? scene::kPedunculatedPolypMaxContact : scene::kSessilePolypMaxContact;
    if (*m.tissueContactFraction <= bar)
        return "";
    return a.id + ": " + std::to_string(static_cast<int>(std::lround(100.0 * *m.tissueContactFraction))) +
           " % of its surface lies against tissue on the final tets; a " + (stalked ? "pedunculated" : "sessile") +
           " polyp stands in the cavity with at most " + std::to_string(static_cast<int>(std::lround(100.0 * bar))) +
           " %";
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
        if (asked.kind == clinical::PathologyKind::Polyp && contact.volumeMm3 > 0.0)
            pd.tissueContactFraction =
                tissueContactFraction(tets, adjacent, pd.regionId, boundary,
                                      tissueLayerParamsFor(spec).endometriumThicknessMm + kDrapeMarginMm);
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
    for (std::size_t i = 0; i < spec.pathologies.size() && i < c.pathologies.size(); ++i)
        if (auto w = seatingWarning(spec.pathologies[i], c.pathologies[i]); !w.empty())
            out.seatingWarnings.push_back(w);
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
        if (p.attachment && m.tissueContactFraction) {
            const bool stalked = *p.attachment == clinical::PolypAttachment::Pedunculated;
            row(p.id + " against tissue %",
                "<= " + mm(100.0 * (stalked ? scene::kPedunculatedPolypMaxContact : scene::kSessilePolypMaxContact)),
                mm(100.0 * *m.tissueContactFraction));
        }
    }
    return t;
}

} // namespace hs::generate
