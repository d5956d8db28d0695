#include "hs/io/TexturedSurface.h"

#include "hs/io/AtomicFile.h"

#include <iomanip>
#include <locale>
#include <sstream>

namespace hs::io {

std::string texturedObjText(const SurfaceMesh& mesh, const std::vector<std::array<float, 2>>& uv,
                            const TexturedObjOptions& options) {
    std::ostringstream s;
    s.imbue(std::locale::classic());
    s << "# " << options.comment << '\n';
    if (!options.materialLibrary.empty())
        s << "mtllib " << options.materialLibrary << '\n';
    s << std::setprecision(17);
    for (const Vec3& p : mesh.points)
        s << "v " << p.x << ' ' << p.y << ' ' << p.z << '\n';
    s << std::setprecision(9);
    for (const auto& q : uv)
        s << "vt " << q[0] << ' ' << q[1] << '\n';
    if (!options.materialLibrary.empty())
        s << "usemtl " << options.material << '\n';
    for (const auto& t : mesh.triangles)
        s << "f " << t[0] + 1 << '/' << t[0] + 1 << ' ' << t[1] + 1 << '/' << t[1] + 1 << ' ' << t[2] + 1 << '/'
          << t[2] + 1 << '\n';
    return s.str();
}

Status writeTexturedObj(const SurfaceMesh& mesh, const std::vector<std::array<float, 2>>& uv, const std::string& path,
                        const TexturedObjOptions& options) {
    HS_TRY(validate(mesh));
    if (uv.size() != mesh.points.size())
        return fail(ErrorCode::InvalidInput, path + ": " + std::to_string(uv.size()) + " texture coordinates for " +
                                                 std::to_string(mesh.points.size()) + " points");
    return writeFileAtomically(path, texturedObjText(mesh, uv, options));
}

} // namespace hs::io
