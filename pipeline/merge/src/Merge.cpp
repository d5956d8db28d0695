// The merge stage: cover each pathology, unite the covers with the organ, label faces, assemble the RegionModel.
#include "hs/merge/Merge.h"

#include "MergeCgal.h"

#include "hs/clinical/Tissue.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace hs::merge {
namespace {

bool isCavityTissue(std::int32_t tissue) {
    const auto t = static_cast<clinical::SurfaceTissue>(tissue);
    return t == clinical::SurfaceTissue::Endometrium || t == clinical::SurfaceTissue::CervicalCanal ||
           t == clinical::SurfaceTissue::TubalOstium;
}

/// The wall tissue draped over a pathology: a surface at `cover` mm around it. Offsetting the vertices along their
/// normals folds wherever the surface is concave with a radius below `cover` (the voxel-scale creases of a grown
/// shape), so the cover is an alpha wrap with that offset instead: closed, manifold and free of self-intersections by
/// construction, and creases narrower than alpha are bridged rather than followed. Alpha is twice the cover (at
/// least 1 mm): the wrap's triangles are about that size, fine enough for a 0.8 mm shell and coarse enough to keep
/// the corefinement fast.
SurfaceMesh coverOf(const SurfaceMesh& surface, double cover) {
    return detail::offsetWrap(surface, std::max(1.0, 2.0 * cover), cover);
}

std::vector<Vec3> faceCentres(const SurfaceMesh& mesh) {
    std::vector<Vec3> c;
    c.reserve(mesh.triangles.size());
    for (const Triangle& t : mesh.triangles)
        c.push_back((mesh.points[static_cast<std::size_t>(t[0])] + mesh.points[static_cast<std::size_t>(t[1])] +
                     mesh.points[static_cast<std::size_t>(t[2])]) /
                    3.0);
    return c;
}

SurfaceMesh outwardOriented(SurfaceMesh mesh) {
    if (enclosedVolume(mesh) < 0.0)
        for (Triangle& t : mesh.triangles)
            std::swap(t[1], t[2]);
    return mesh;
}

/// Outline labels: "tissue" from the organ face it came from (or, on a cover, the organ face nearest to it);
/// "pathology" the 1-based index of the pathology a cover face drapes.
void labelOutline(SurfaceMesh& outline, const SurfaceMesh& organ, const std::vector<SurfaceMesh>& covers) {
    const std::vector<Vec3> centres = faceCentres(outline);
    const auto& organTissue = organ.faceLabels.at(clinical::kSurfaceTissueLabel);
    std::vector<std::size_t> organFace;
    std::vector<double> organDist;
    detail::nearestFaces(organ, centres, organFace, organDist);
    std::vector<std::int32_t> tissue(centres.size()), pathology(centres.size(), 0);
    std::vector<double> best = organDist;
    for (std::size_t c = 0; c < covers.size(); ++c) {
        std::vector<std::size_t> face;
        std::vector<double> dist;
        detail::nearestFaces(covers[c], centres, face, dist);
        for (std::size_t i = 0; i < centres.size(); ++i)
            if (dist[i] < best[i]) {
                best[i] = dist[i];
                pathology[i] = static_cast<std::int32_t>(c + 1);
            }
    }
    for (std::size_t i = 0; i < centres.size(); ++i)
        tissue[i] = organTissue[organFace[i]];
    outline.faceLabels[clinical::kSurfaceTissueLabel] = std::move(tissue);
    outline.faceLabels[kPathologyLabel] = std::move(pathology);
}

/// Pathology labels: "contact" = what lies across each face (wall, draped endometrium, draped serosa).
void labelPathology(SurfaceMesh& surface, const SurfaceMesh& organ) {
    const std::vector<Vec3> centres = faceCentres(surface);
    const std::vector<bool> inWall = detail::insideOf(organ, centres);
    std::vector<std::size_t> face;
    std::vector<double> dist;
    detail::nearestFaces(organ, centres, face, dist);
    const auto& organTissue = organ.faceLabels.at(clinical::kSurfaceTissueLabel);
    std::vector<std::int32_t> contact(centres.size());
    for (std::size_t i = 0; i < centres.size(); ++i)
        contact[i] = static_cast<std::int32_t>(inWall[i]                              ? Contact::Myometrium
                                               : isCavityTissue(organTissue[face[i]]) ? Contact::Endometrium
                                                                                      : Contact::Serosa);
    surface.faceLabels[kContactLabel] = std::move(contact);
}

std::string mm(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f", v);
    return text;
}

double nearest(const SurfaceMesh& mesh, const std::vector<Vec3>& points) {
    std::vector<std::size_t> face;
    std::vector<double> dist;
    detail::nearestFaces(mesh, points, face, dist);
    return dist.empty() ? 0.0 : *std::min_element(dist.begin(), dist.end());
}

/// Why the displaced organ crossed itself, for the refusal: where, and each pathology with its size and how far it
/// lies from the crossings (the ones that pushed the wall there lie nearest), and the room between the pathologies.
std::string crowdedWall(const SurfaceMesh& organ, const std::vector<std::pair<std::size_t, std::size_t>>& crossing,
                        const std::vector<pathology::GrownPathology>& pathologies) {
    const auto centres = faceCentres(organ);
    std::vector<Vec3> at;
    Vec3 mean;
    for (const auto& [a, b] : crossing)
        for (const auto f : {a, b}) {
            at.push_back(centres[f]);
            mean += centres[f];
        }
    mean = mean / static_cast<double>(std::max<std::size_t>(1, at.size()));
    std::string text = "merge: the organ, displaced to make room for the pathologies, intersects itself (" +
                       std::to_string(crossing.size()) + " triangle pairs about (" + mm(mean.x) + ", " + mm(mean.y) +
                       ", " + mm(mean.z) + ") mm): the pathologies push the wall too far for the room there;";
    for (std::size_t i = 0; i < pathologies.size(); ++i) {
        const auto& p = pathologies[i];
        text += std::string(i ? "," : "") + " " + std::string(clinical::toString(p.kind)) + " '" + p.id + "' (" +
                mm(p.descriptors.sizeMm) + " mm) " + mm(nearest(p.surface, at)) + " mm from the crossings";
    }
    for (std::size_t i = 0; i < pathologies.size(); ++i)
        for (std::size_t j = i + 1; j < pathologies.size(); ++j)
            text += "; '" + pathologies[i].id + "' and '" + pathologies[j].id + "' lie " +
                    mm(nearest(pathologies[j].surface, pathologies[i].surface.points)) + " mm apart";
    return text;
}

} // namespace

Result<MergeResult> mergeBody(const pathology::PathologyResult& grown, const MergeParams& params, Progress& progress) {
    MergeResult result;
    if (!std::isfinite(params.coverMm) || params.coverMm <= 0.0)
        return fail(ErrorCode::InvalidInput,
                    "merge: coverMm must be positive (got " + std::to_string(params.coverMm) + ")");
    if (grown.organ.faceLabels.count(clinical::kSurfaceTissueLabel) == 0)
        return fail(ErrorCode::InvalidInput, "merge: the organ has no \"tissue\" face label");
    const SurfaceMesh organ = outwardOriented(grown.organ);
    std::vector<SurfaceMesh> covers;
    {
        ScopedStepTimer timer(result.timings, "cover");
        if (!analyzeTopology(organ).isWatertight())
            return fail(ErrorCode::InvalidInput, "merge: the organ surface is not closed and manifold");
        if (const auto crossing = detail::selfIntersections(organ); !crossing.empty())
            return fail(ErrorCode::InvalidInput, crowdedWall(organ, crossing, grown.pathologies));
        for (const auto& p : grown.pathologies) {
            HS_TRY(progress.check("merge"));
            if (!analyzeTopology(p.surface).isWatertight())
                return fail(ErrorCode::InvalidInput, "merge: pathology '" + p.id + "' is not closed and manifold");
            if (const std::size_t n = detail::selfIntersections(p.surface).size(); n > 0)
                return fail(ErrorCode::InvalidInput, "merge: pathology '" + p.id + "' intersects itself (" +
                                                         std::to_string(n) + " triangle pairs)");
            SurfaceMesh cover = outwardOriented(coverOf(p.surface, params.coverMm));
            if (cover.triangles.empty() || !analyzeTopology(cover).isWatertight())
                return fail(ErrorCode::Internal, "merge: the cover of pathology '" + p.id + "' is not closed");
            covers.push_back(std::move(cover));
        }
    }
    progress.report("merge.cover", 0.2);
    SurfaceMesh outline;
    {
        ScopedStepTimer timer(result.timings, "union");
        std::vector<const SurfaceMesh*> others;
        for (const auto& c : covers)
            others.push_back(&c);
        auto united = detail::unite(organ, others);
        if (!united.ok())
            return united.failure();
        outline = std::move(*united);
        result.timings.step("union").counts.emplace_back("triangles",
                                                         static_cast<std::int64_t>(outline.triangles.size()));
    }
    HS_TRY(progress.check("merge"));
    progress.report("merge.union", 0.6);
    {
        ScopedStepTimer timer(result.timings, "labels");
        labelOutline(outline, organ, covers);
        RegionSurface wall;
        wall.surface = std::move(outline);
        wall.regionId = 0;
        wall.name = "wall";
        result.body.surfaces.push_back(std::move(wall));
        for (std::size_t i = 0; i < grown.pathologies.size(); ++i) {
            RegionSurface rs;
            rs.surface = outwardOriented(grown.pathologies[i].surface);
            rs.surface.faceLabels.clear();
            rs.surface.vertexLabels.clear();
            labelPathology(rs.surface, organ);
            rs.regionId = static_cast<std::int32_t>(i + 1);
            rs.name = grown.pathologies[i].id;
            result.body.surfaces.push_back(std::move(rs));
        }
    }
    progress.report("merge.labels", 0.8);
    if (params.validate) {
        ScopedStepTimer timer(result.timings, "validate");
        if (auto status = validate(result.body); !status.ok())
            return fail(ErrorCode::InvalidInput, "merge: the merged body is invalid: " + status.error().detail);
    }
    progress.report("merge.validate", 1.0);
    return result;
}

} // namespace hs::merge
