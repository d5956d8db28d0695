#pragma once
/// scene.scn and surface.obj: the scene for SOFA (https://www.sofa-framework.org) with stock components only
/// (private to hs::scene).

#include "hs/scene/Scene.h"

#include <string>

namespace hs::scene::detail {

/// The SOFA scene (XML). Units: mm, kg, s, so stresses come out in kPa and the materials' Young's moduli are
/// written unchanged; densities are converted to kg/mm^3. The volume comes from mesh.msh (MeshGmshLoader) into one
/// MechanicalObject; the vertices of the tets labelled kSupportLabel are held by a FixedProjectiveConstraint; each
/// region gets its own TetrahedronFEMForceField on its tets, linked to that MechanicalObject; and surface.obj with the
/// albedo map is an OglModel mapped onto the tets. See docs/scene-format.md for the SOFA sources relied on.
std::string sofaScene(const Scene& scene, bool hasAlbedo);

/// The visual surface as Wavefront OBJ with texture coordinates (v, vt, f v/vt), mm; V flipped to OBJ's
/// bottom-left origin.
std::string visualObj(const Scene& scene);

} // namespace hs::scene::detail
