#pragma once
/// What the pathology stage reads off the organ: which side of the wall each vertex and face belongs to, the
/// cavity's axis and landmarks, the corpus' dimensions, rays and nearest faces.

#include "hs/core/Result.h"
#include "hs/core/SurfaceMesh.h"

#include <cstdint>
#include <optional>
#include <vector>

namespace hs::pathology::detail {

enum class Side : std::int8_t { Cavity = 1, Serosa = 2 };

struct RayHit {
    double t = 0.0;
    std::size_t face = 0;
    Vec3 point;
};

struct OrganInfo {
    const SurfaceMesh* mesh = nullptr;
    std::vector<Side> faceSide;   ///< cavity side: endometrium, ostia, canal; serosa side: serosa, ectocervix
    std::vector<Side> vertexSide; ///< cavity when any incident face is on the cavity side
    Vec3 internalOs;              ///< centre of the ring where canal meets endometrium
    Vec3 cavityFundus;            ///< the cavity point farthest from the internal os
    Vec3 axis;                    ///< unit, internal os -> cavity fundus
    Vec3 lateral;                 ///< unit, towards the patient's right (+x of the organ frame), normal to axis
    Vec3 anterior;                ///< unit, axis x lateral
    Vec3 cavityCenter;
    Vec3 cornuRight, cornuLeft; ///< centres of the tubal ostia
    /// Whether the organ labels each ostium (its faces); the cornu is then that ostium's centre, else a ray's hit.
    bool ostiumRight = false, ostiumLeft = false;
    double cavityLengthMm = 0.0; ///< internal os to cavity fundus
    double cavityWidthMm = 0.0;  ///< between the ostia
    double corpusLengthMm = 0.0; ///< internal os to the fundal serosa along the axis
    double corpusWidthMm = 0.0;  ///< lateral extent of the corpus
    double corpusDepthMm = 0.0;  ///< anteroposterior extent of the corpus

    /// First hit of the ray with a face of `side` (any side when unset).
    std::optional<RayHit> ray(const Vec3& origin, const Vec3& dir, std::optional<Side> side, double tMin = 1e-6) const;
    /// Nearest face to p and its distance, restricted to `side` when set.
    std::pair<std::size_t, double> nearestFace(const Vec3& p, std::optional<Side> side = std::nullopt) const;
};

/// Fails with InvalidInput when the mesh has no "tissue" label, no endometrium, canal or serosa.
Result<OrganInfo> analyzeOrgan(const SurfaceMesh& organ);

} // namespace hs::pathology::detail
