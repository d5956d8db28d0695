// One mesh reader (the format chosen by HS_FUZZ_EXTENSION, e.g. ".obj"), through the public entry point readMesh.
// Properties: a mesh the reader accepts passes hs::validate; an error names the file.

#include "FuzzSupport.h"
#include "hs/io/MeshIO.h"

#include <variant>

#ifndef HS_FUZZ_EXTENSION
#error "HS_FUZZ_EXTENSION names the format, e.g. \".obj\""
#endif

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string path = hs::fuzz::writeScratch(std::string("input") + HS_FUZZ_EXTENSION, data, size);
    if (path.empty())
        return 0;
    // Small limits keep a hostile count from making the run slow rather than failing it.
    hs::io::ReadLimits limits;
    limits.maxPoints = 1'000'000;
    limits.maxCells = 4'000'000;
    limits.maxFileBytes = 64 << 20;
    const auto mesh = hs::io::readMesh(path, limits);
    if (mesh.ok()) {
        if (const auto* surface = std::get_if<hs::SurfaceMesh>(&*mesh))
            hs::fuzz::check(hs::validate(*surface).ok(), "an accepted surface passes hs::validate");
        else
            hs::fuzz::check(hs::validate(std::get<hs::TetMesh>(*mesh)).ok(), "an accepted tet mesh passes validate");
    } else {
        hs::fuzz::check(mesh.error().detail.find(path) != std::string::npos, "an error names the file",
                        mesh.error().detail);
    }
    return 0;
}
