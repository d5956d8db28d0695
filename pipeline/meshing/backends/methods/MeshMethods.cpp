// Run-time choice of the meshing method; the optional backends are compiled in when their targets exist.
#include "hs/meshing/BaselineMeshers.h"
#include "hs/meshing/ParticleMesher.h"

namespace hs::meshing {

bool methodAvailable(MeshMethod method) {
    switch (method) {
    case MeshMethod::Particle:
        return true;
#ifdef HS_HAVE_TETGEN
    case MeshMethod::TetGen:
        return true;
#endif
#ifdef HS_HAVE_CGAL_MESH3
    case MeshMethod::Cgal:
        return true;
#endif
    default:
        return false;
    }
}

LibraryVersions methodLibraryVersions(MeshMethod method) {
#ifdef HS_HAVE_TETGEN
    if (method == MeshMethod::TetGen)
        return {{"tetgen", HS_TETGEN_VERSION}};
#else
    (void)method;
#endif
    return {};
}

Result<MeshResult> meshWith(MeshMethod method, const RegionModel& body, const MeshParams& params, Progress& progress) {
    switch (method) {
    case MeshMethod::Particle:
        return meshParticles(body, params, progress);
#ifdef HS_HAVE_TETGEN
    case MeshMethod::TetGen:
        return meshTetGen(body, params, progress);
#endif
#ifdef HS_HAVE_CGAL_MESH3
    case MeshMethod::Cgal:
        return meshCgal(body, params, progress);
#endif
    default:
        break;
    }
    return fail(ErrorCode::Unsupported,
                "meshing method '" + std::string(methodName(method)) +
                    "' is not built into this program (see HS_WITH_TETGEN / HS_WITH_CGAL_MESH3)");
}

} // namespace hs::meshing
