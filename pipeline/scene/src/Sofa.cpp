// The SOFA scene and the OBJ its visual model loads.

#include "Sofa.h"

#include "Format.h"

#include "hs/core/Units.h"
#include "hs/io/TexturedSurface.h"

#include <algorithm>
#include <iomanip>
#include <locale>
#include <map>
#include <sstream>
#include <vector>

namespace hs::scene::detail {

namespace {

constexpr double kKgPerM3ToKgPerMm3 = 1e-9;

std::string number(double v) {
    return formatNumber(v); // shortest text that reads back to v: "0.47", not "0.46999999999999997"
}

/// Volume-weighted mean density of the body, kg/m^3: SOFA's MeshMatrixMass takes one density per mass component,
/// and all tissues share 1050 kg/m^3 by default (docs/references.md [SoftTissue]), so one mass for the body loses
/// nothing by default.
double meanDensity(const Scene& scene) {
    std::map<std::int32_t, double> densityOfRegion;
    for (const auto& m : scene.materials)
        densityOfRegion[m.regionId] = m.material.densityKgPerM3;
    double mass = 0.0, volume = 0.0;
    for (const auto& [region, v] : regionVolumes(scene.tets)) {
        mass += densityOfRegion[region] * v;
        volume += v;
    }
    return volume > 0.0 ? mass / volume : 1050.0;
}

/// The points the support label's tets hold, ascending and unique; empty when the scene has no support label.
std::vector<std::int32_t> heldPoints(const Scene& scene) {
    std::vector<std::int32_t> points;
    for (const auto& label : scene.labels)
        if (label.name == kSupportLabel && label.element == LabelElement::Tet)
            for (const std::int32_t t : label.indices)
                for (const std::int32_t v : scene.tets.tets[static_cast<std::size_t>(t)])
                    points.push_back(v);
    std::sort(points.begin(), points.end());
    points.erase(std::unique(points.begin(), points.end()), points.end());
    return points;
}

template <class Range>
void writeList(std::ostream& s, const Range& values) {
    bool first = true;
    for (const auto v : values) {
        s << (first ? "" : " ") << v;
        first = false;
    }
}

/// Held points as a FixedProjectiveConstraint (SOFA >= v24.06; FixedConstraint before): their displacement is
/// projected to zero, so the body hangs there instead of falling under gravity.
void writeSupport(std::ostream& s, const Scene& scene) {
    const auto held = heldPoints(scene);
    if (held.empty()) {
        s << "        <!-- no support label: nothing holds the body -->\n";
        return;
    }
    s << "        <!-- the cervix, held by the vagina and the cardinal and uterosacral ligaments (label "
      << kSupportLabel << ") -->\n"
      << "        <FixedProjectiveConstraint name=\"support\" template=\"Vec3d\" mstate=\"@dofs\" "
         "topology=\"@topology\" indices=\"";
    writeList(s, held);
    s << "\"/>\n";
}

/// One child node per material. Its TetrahedronSetTopologyContainer holds the region's tets with the body's point
/// indices and the loader's positions, so its TetrahedronFEMForceField computes on the parent's MechanicalObject,
/// named by the `mstate` link (SOFA's Node::getMechanicalState would also find it in the parent: the child has
/// none of its own). Every tet is in exactly one region, so each tet gets exactly one force field.
void writeRegions(std::ostream& s, const Scene& scene) {
    std::map<std::int32_t, std::vector<std::size_t>> tetsOfRegion;
    for (std::size_t t = 0; t < scene.tets.tetCount(); ++t)
        tetsOfRegion[scene.tets.regionOf(t)].push_back(t);
    for (const auto& m : scene.materials) {
        s << "        <!-- " << m.name << " (" << toString(m.tissue) << "), region " << m.regionId << " -->\n"
          << "        <Node name=\"region" << m.regionId << "\">\n"
          << "            <TetrahedronSetTopologyContainer name=\"topology\" position=\"@../loader.position\" "
             "tetrahedra=\"";
        bool first = true;
        for (const std::size_t t : tetsOfRegion[m.regionId]) {
            s << (first ? "" : " ");
            writeList(s, scene.tets.tets[t]);
            first = false;
        }
        s << "\"/>\n"
          << "            <TetrahedronFEMForceField name=\"fem\" template=\"Vec3d\" mstate=\"@../dofs\" "
             "topology=\"@topology\" method=\"large\" youngModulus=\""
          << number(m.material.youngsModulusKpa) << "\" poissonRatio=\"" << number(m.material.poissonRatio) << "\"/>\n"
          << "        </Node>\n";
    }
}

} // namespace

std::string sofaScene(const Scene& scene, bool hasAlbedo) {
    std::ostringstream s;
    s.imbue(std::locale::classic());
    s << "<?xml version=\"1.0\"?>\n"
      << "<!-- hysteroscene scene package: units mm, kg, s (stress in kPa). Stock SOFA components only. -->\n"
      << "<Node name=\"root\" dt=\"0.01\" gravity=\"0 0 -9810\">\n"
      << "    <RequiredPlugin pluginName=\"Sofa.Component.AnimationLoop Sofa.Component.Constraint.Projective "
         "Sofa.Component.IO.Mesh Sofa.Component.StateContainer Sofa.Component.Topology.Container.Dynamic "
         "Sofa.Component.SolidMechanics.FEM.Elastic Sofa.Component.Mass Sofa.Component.ODESolver.Backward "
         "Sofa.Component.LinearSolver.Iterative Sofa.Component.Mapping.Linear Sofa.GL.Component.Rendering3D\"/>\n"
      << "    <DefaultAnimationLoop/>\n"
      << "    <Node name=\"tissue\">\n"
      << "        <EulerImplicitSolver name=\"odeSolver\" rayleighStiffness=\"0.1\" rayleighMass=\"0.1\"/>\n"
      << "        <CGLinearSolver name=\"linearSolver\" iterations=\"100\" tolerance=\"1e-9\" threshold=\"1e-9\"/>\n"
      << "        <MeshGmshLoader name=\"loader\" filename=\"mesh.msh\"/>\n"
      << "        <MechanicalObject name=\"dofs\" template=\"Vec3d\" src=\"@loader\"/>\n"
      << "        <TetrahedronSetTopologyContainer name=\"topology\" src=\"@loader\"/>\n"
      << "        <MeshMatrixMass name=\"mass\" massDensity=\"" << number(meanDensity(scene) * kKgPerM3ToKgPerMm3)
      << "\" topology=\"@topology\"/>\n";
    writeSupport(s, scene);
    writeRegions(s, scene);
    s << "        <Node name=\"visual\">\n"
      << "            <OglModel name=\"surface\" filename=\"surface.obj\"";
    if (hasAlbedo)
        s << " texturename=\"maps/albedo.png\"";
    s << "/>\n"
      << "            <BarycentricMapping name=\"mapping\" input=\"@../dofs\" output=\"@surface\"/>\n"
      << "        </Node>\n"
      << "    </Node>\n"
      << "</Node>\n";
    return s.str();
}

std::string visualObj(const Scene& scene) {
    // The scene's uvs have their origin at the image's top left, OBJ's at its bottom left.
    std::vector<std::array<float, 2>> uv;
    uv.reserve(scene.surface.uvs.size());
    for (const auto& q : scene.surface.uvs)
        uv.push_back({q[0], 1.0f - q[1]});
    io::TexturedObjOptions options;
    options.comment = "hysteroscene visual surface, mm";
    return io::texturedObjText(scene.surface.mesh, uv, options);
}

} // namespace hs::scene::detail
