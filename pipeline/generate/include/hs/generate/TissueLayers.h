#pragma once
/// The wall's tissue layers as tetrahedral regions: the endometrium lining the cavity and the cervix around the
/// canal, carved out of the meshed wall (the myometrium keeps the rest).
///
/// Every wall tet is assigned by its nearest lining face, measured through the wall: a multi-source Dijkstra over
/// the tets' face adjacency that carries each tet's nearest source triangle along (distance propagation, after
/// Danielsson's vector propagation for distance maps, 1980). The sources are the boundary faces of the mesh with the
/// organ's tissue labels: the cavity's (endometrium, tubal ostia) and the canal's (cervical canal, ectocervix).
///  - cervix: wall tets whose nearest lining face is the canal's, i.e. the tissue around the canal from the external
///    os up to the internal os, where the canal's and the cavity's nearest regions meet;
///  - endometrium: wall tets whose nearest lining face is the cavity's and whose centroid lies within the lining's
///    thickness of it.
/// The endometrium also covers what lies in the cavity: pathology tets with a face on the cavity (the faces draped
/// over a submucosal myoma, a polyp's surface) become endometrium too, one tet deep.
/// The layer follows the mesh: its faces are tet faces, so its thickness is resolved to about an edge length; the
/// result reports the thickness it reached (volume / lining area).

#include "hs/core/SurfaceMesh.h"
#include "hs/core/TetMesh.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace hs::generate {

struct TissueLayerParams {
    double endometriumThicknessMm = 3.0; ///< mm, one layer (half the double-layer thickness ultrasound reports)
    bool cervix = true;                  ///< carve the cervix out of the wall
    bool coverPathologies = true;        ///< pathology tets on the cavity become endometrium
};

enum class WallLayer : std::uint8_t { Myometrium = 0, Endometrium = 1, Cervix = 2 };

struct TissueLayers {
    std::vector<WallLayer> layer;    ///< per tet; pathology tets: Endometrium for the cover, else Myometrium
    std::size_t endometriumTets = 0; ///< of the wall
    std::size_t coverTets = 0;       ///< pathology tets covered
    std::size_t cervixTets = 0;
    double liningAreaMm2 = 0.0;        ///< mm^2, cavity faces of the wall
    double endometriumVolumeMm3 = 0.0; ///< mm^3
    double cervixVolumeMm3 = 0.0;      ///< mm^3
    /// mm, the endometrium's volume per lining area; above the thickness where the cavity curves (the shell wraps
    /// its rim: docs/anatomy.md); 0 without a lining.
    double endometriumVolumePerLiningAreaMm() const {
        return liningAreaMm2 > 0.0 ? endometriumVolumeMm3 / liningAreaMm2 : 0.0;
    }
};

/// The layers of region `wallRegion` of `tets`. `boundary` is extractBoundary(tets) with the organ's face label
/// "tissue" carried over (its vertex label "sourcePoint" maps its points to the tets' points). Faces of `boundary`
/// that are not faces of `tets` are ignored; a mesh without lining faces keeps its wall as myometrium.
TissueLayers tissueLayers(const TetMesh& tets, std::int32_t wallRegion, const SurfaceMesh& boundary,
                          const TissueLayerParams& params);

} // namespace hs::generate
