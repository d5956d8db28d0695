// The training-cohort CSV of `model build --from` (hs/anatomy/TrainingData.h): a user's own segmented organs, one row
// per mesh file. The meshes it names are read from a scratch folder that holds one small valid mesh, "a.obj".
// Property: an error names the CSV or the mesh it is about.

#include "FuzzSupport.h"
#include "hs/anatomy/TrainingData.h"

#include <string>

namespace {

/// The mesh folder, made once: a tetrahedron's surface as "a.obj".
const std::string& meshFolder() {
    static const std::string folder = [] {
        const auto dir = hs::fuzz::scratchFolder() / "meshes";
        std::error_code ec;
        std::filesystem::create_directories(dir, ec);
        const std::string obj = "v 0 0 0\nv 10 0 0\nv 0 10 0\nv 0 0 10\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
        std::FILE* f = std::fopen((dir / "a.obj").c_str(), "wb");
        if (f) {
            std::fwrite(obj.data(), 1, obj.size(), f);
            std::fclose(f);
        }
        return dir.string();
    }();
    return folder;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string& meshes = meshFolder();
    const std::string csv = hs::fuzz::writeScratch("cohort.csv", data, size);
    if (csv.empty())
        return 0;
    const auto set = hs::anatomy::loadTrainingSet(meshes, csv);
    if (!set.ok())
        hs::fuzz::check(set.error().detail.find("cohort.csv") != std::string::npos ||
                            set.error().detail.find(meshes) != std::string::npos,
                        "an error names the CSV or the mesh", set.error().detail);
    return 0;
}
