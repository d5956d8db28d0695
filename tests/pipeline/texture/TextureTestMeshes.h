#pragma once
/// Meshes made in code for the texture tests and benchmarks (no dependency on the mesher).

#include "hs/core/SurfaceMesh.h"
#include "hs/core/TetMesh.h"

namespace hs::test {

/// A cube of side `sizeMm` split into n^3 cells of 6 tetrahedra each; tets whose centroid lies within `radiusMm` of
/// the centre of the top face get region 1 (a "myoma" touching the surface), the rest region 0.
TetMesh makeTetCube(int n, double sizeMm = 20.0, double radiusMm = 6.0);

/// A geodesic sphere of frequency f (10 f^2 + 2 vertices), radius `radiusMm`, squashed to an organ-like ellipsoid,
/// with a broad bump labelled region 1 (myoma) and a narrow tall bump labelled region 2 (polyp); face labels "region"
/// and "contact" (1 on faces of a bump that touch the rest).
SurfaceMesh makeLabelledOrgan(int frequency, double radiusMm = 30.0);

/// Each triangle split into four (shared edge midpoints), labels copied to the children.
SurfaceMesh subdivideMidpoint(const SurfaceMesh& mesh);

/// Pushes two bumps (myoma: broad, polyp: narrow) out of `mesh` along its vertex normals, at the vertices nearest to
/// the given directions from the centre, and labels faces "region" (0, 1 myoma, 2 polyp) and "contact".
void addPathologyBumps(SurfaceMesh& mesh, const Vec3& myomaDir, double myomaRadiusMm, double myomaHeightMm,
                       const Vec3& polypDir, double polypRadiusMm, double polypHeightMm);

} // namespace hs::test
