#pragma once
/// Parametric healthy uterus: one closed, thick-walled surface in a fixed template topology.
///
/// The wall is a single closed surface of genus 0: the serosa (outside) turns at the external os into the
/// ectocervix, runs up the cervical canal into the endometrial cavity and closes at the cavity fundus. The cavity is
/// therefore reachable from outside through the canal, as the hysteroscope reaches it, and the surface bounds the
/// tissue (myometrium and cervical stroma). Every instance has the same vertices and triangles (only positions
/// change), so instances are in correspondence for the statistical shape model.
///
/// Frame (mm): origin at the centre of the external os; before version, +z runs up the cervical canal; +x is lateral
/// (the cornu at ring index 0 lies on +x), +y anterior. Version then tilts the whole organ about the x axis through the
/// external os, so after it +z is the vaginal axis, the direction in which the scope enters.

#include "hs/clinical/Tissue.h"
#include "hs/core/Result.h"
#include "hs/core/SurfaceMesh.h"

#include <cstdint>
#include <string>
#include <vector>

namespace hs::anatomy {

/// Shape controls. Defaults: a nulliparous woman of about 30 (see docs/anatomy.md for the source of each figure).
struct UterusShapeParams {
    double lengthMm = 74.0;                ///< mm, external os to fundal serosa along the (bent) axis
    double widthMm = 43.0;                 ///< mm, largest transverse outer width of the corpus
    double apDepthMm = 38.0;               ///< mm, largest anteroposterior outer depth of the corpus
    double fundalWallMm = 12.3;            ///< mm, fundal myometrium, cavity to serosa on the midline
    double cavityLengthMm = 31.5;          ///< mm, internal os to the cavity fundus on the midline
    double cavityWidthMm = 28.5;           ///< mm, between the two cornua (the tubal ostia)
    double cavityDepthMm = 8.0;            ///< mm, anteroposterior opening of the (distended) cavity
    double cornualAngleDeg = 63.0;         ///< degree, between the lateral cavity wall and the intercornual line
    double internalOsWidthMm = 7.5;        ///< mm, canal width at the internal os
    double cervixLengthMm = 30.0;          ///< mm, external os to the outer isthmus (where the corpus widens)
    double cervixDiameterMm = 28.5;        ///< mm, outer diameter of the cervix
    double versionDeg = 0.0;               ///< degree, cervix axis vs. vaginal axis; > 0 anteverted, < 0 retroverted
    double flexionDeg = 20.0;              ///< degree, corpus axis vs. cervix axis; > 0 anteflexed, < 0 retroflexed
    double lateralAsymmetry = 0.0;         ///< fraction; +x half-widths scaled by (1 + a), -x by (1 - a)
    double apAsymmetry = 0.0;              ///< fraction; anterior half-depths scaled by (1 + a), posterior (1 - a)
    double cornualHeightAsymmetryMm = 0.0; ///< mm; the +x cornu is raised by h/2, the -x cornu lowered by h/2
};

/// Where the rings of the template lie. Vertex 0 is the fundal pole of the serosa; then `ringCount()` rings of
/// `around` vertices: serosa from fundus to external os, ectocervix rim, canal from external to internal os, cavity
/// up to the cornua, cavity fundus cap; the last vertex is the pole of the cavity fundus. Vertex j of a ring lies
/// at angle 2*pi*j/around from +x towards +y (j = 0: +x cornu side, around/4: anterior).
struct TemplateLayout {
    int around = 48;     ///< vertices per ring (a multiple of 4)
    int outerRings = 36; ///< serosa rings, fundus to external os
    int osRings = 3;     ///< rings inside the ectocervix rim
    int canalRings = 10; ///< canal rings; the first lies at the external os, the last at the internal os
    int cavityRings = 14;
    int capRings = 6; ///< rings of the cavity fundus cap above the cornua

    int ringCount() const { return outerRings + osRings + canalRings + cavityRings + capRings; }
    int vertexCount() const { return 2 + ringCount() * around; }
    int faceCount() const { return 2 * around * ringCount(); }
    int firstCanalRing() const { return outerRings + osRings; }
    int internalOsRing() const { return firstCanalRing() + canalRings - 1; }
    int lastCavityRing() const { return internalOsRing() + cavityRings; } ///< the ring through the cornua
    int vertex(int ring, int j) const { return 1 + ring * around + ((j % around) + around) % around; }
    int innerPole() const { return vertexCount() - 1; }
};

struct UterusResult {
    SurfaceMesh mesh;                  ///< face label clinical::kSurfaceTissueLabel (clinical::SurfaceTissue)
    TemplateLayout layout;             ///< how to find rings and landmarks in `mesh`
    std::vector<std::string> warnings; ///< e.g. a cavity narrowed to keep the minimum wall
};

/// Builds the organ. Cavity and canal are narrowed where they would leave less than `kMinimumWallMm` of wall in a
/// cross-section (a warning says so). Fails with InvalidInput naming a control outside its range or a combination
/// that leaves no room for the cervical canal.
[[nodiscard]] Result<UterusResult> generateUterus(const UterusShapeParams& params, const TemplateLayout& layout = {});

/// Wall kept in every cross-section of the generator, mm (the organ checks require >= 5 mm in 3-D).
inline constexpr double kMinimumWallMm = 6.0;

/// mm; the canal and the cavity are at least twice this across in every direction (docs/anatomy.md, "Open canal").
inline constexpr double kOpenCanalHalfWidthMm = 2.0;

/// Widens every ring of the canal and of the cavity below the cornua (internal os included) where it is narrower
/// than `kOpenCanalHalfWidthMm` from its centre, moving those vertices out in the ring's plane. `generateUterus`
/// builds its rings that wide; a shape model's instance is a linear combination of such organs plus a residual,
/// which the floor does not survive (the default model's samples had canals 3.0-3.5 mm across). Returns the largest
/// move in mm.
double openPassage(SurfaceMesh& mesh, const TemplateLayout& layout);

/// The template's triangles and labels (positions all zero): identical for every instance of `layout`.
SurfaceMesh uterusTemplate(const TemplateLayout& layout = {});

/// Clinical dimensions read off an instance of the template (landmarks by vertex index), mm unless noted.
struct UterusDimensions {
    double lengthMm = 0.0;       ///< external os to fundal serosa, along the centreline
    double corpusLengthMm = 0.0; ///< internal os to fundal serosa, along the centreline
    double cervixLengthMm = 0.0; ///< external to internal os, along the canal
    double widthMm = 0.0;        ///< largest lateral outer width of the corpus
    double apDepthMm = 0.0;      ///< largest anteroposterior outer depth of the corpus
    double cavityLengthMm = 0.0; ///< internal os to cavity fundus, along the centreline
    double cavityWidthMm = 0.0;  ///< between the two cornua
    double cavityAreaCm2 = 0.0;  ///< coronal area of the cavity outline, cm^2
    double internalOsWidthMm = 0.0;
    double cervixDiameterMm = 0.0;  ///< outer AP diameter at mid-cervix
    double fundalWallMm = 0.0;      ///< cavity fundus to serosa fundus
    double flexionDeg = 0.0;        ///< angle between corpus axis and canal axis, > 0 towards anterior
    double ellipsoidVolumeMl = 0.0; ///< clinical estimate L * W * AP * 0.523, mL
    double tissueVolumeMl = 0.0;    ///< volume enclosed by the wall surface, mL
    double cavityVolumeMl = 0.0;    ///< cavity and canal, closed at the external os, mL
};

/// Measures an instance of `layout` (a generator output or a model sample). Fails with InvalidInput when the mesh
/// does not have the layout's vertex count.
[[nodiscard]] Result<UterusDimensions> measureUterus(const SurfaceMesh& mesh, const TemplateLayout& layout);

/// Clinical ultrasound volume estimate of a uterus, L * W * AP * 0.523 (docs/references.md [Ellipsoid]), mL from mm.
double ellipsoidVolumeMl(double lengthMm, double widthMm, double apDepthMm);

/// Dimensions of a body grown from an instance of the template (pathologies added, merged, meshed), by measureUterus
/// itself: every vertex of `organ` (a template instance in the body's frame, near the body) is moved along its
/// normal onto the body's `serosaFaces` (serosa rings and the fundal pole) or `cavityFaces` (canal, cavity, cavity
/// pole), to the crossing nearest to it within 20 mm with a face that faces its way (so a thin cavity's other wall
/// is never taken for its own). A vertex with no crossing stays where `organ` has it: where a pathology has taken
/// the place of the cavity's wall and `cavityFaces` leave it out, the wall runs beneath it as in `organ`. Fails with
/// InvalidInput when `organ` is not an instance of `layout`.
/// How many of the template's vertices measureBody moved onto the body, and how many found no crossing and stayed
/// (a pole that stays follows its ring).
struct BodyCrossings {
    std::size_t serosaVertices = 0; ///< serosa rings and the fundal pole
    std::size_t serosaStayed = 0;
    std::size_t cavityVertices = 0; ///< canal and cavity rings and the cavity pole
    std::size_t cavityStayed = 0;
};

[[nodiscard]] Result<UterusDimensions> measureBody(const SurfaceMesh& organ, const TemplateLayout& layout,
                                                   const SurfaceMesh& body,
                                                   const std::vector<std::int32_t>& serosaFaces,
                                                   const std::vector<std::int32_t>& cavityFaces,
                                                   BodyCrossings* crossings = nullptr);

} // namespace hs::anatomy
