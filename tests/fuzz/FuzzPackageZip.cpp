// The scene package reader on a zipped package: unzipScenePackage (entry names, links, sizes, ratios) into a
// temporary folder, then every file checked and parsed. Properties: an error names the zip; the temporary folder
// is gone afterwards.

#include "FuzzSupport.h"
#include "hs/scene/ScenePackage.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string path = hs::fuzz::writeScratch("package.zip", data, size);
    if (path.empty())
        return 0;
    hs::scene::PackageReadLimits limits;
    limits.maxFileBytes = 16 << 20;
    limits.maxTotalBytes = 64 << 20;
    const auto scene = hs::scene::readScenePackage(path, limits);
    if (!scene.ok())
        hs::fuzz::check(scene.error().detail.find(path) != std::string::npos, "an error names the zip",
                        scene.error().detail);
    return 0;
}
