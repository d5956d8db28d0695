// Exemplar image loading (user images through OpenImageIO, checked against the synthesis limits).
// Property: an error names the file.

#include "FuzzSupport.h"
#include "hs/texture/Bake.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string path = hs::fuzz::writeScratch("exemplar.png", data, size);
    if (path.empty())
        return 0;
    const auto image = hs::texture::readExemplarFile(path);
    if (!image.ok())
        hs::fuzz::check(image.error().detail.find(path) != std::string::npos, "an error names the file",
                        image.error().detail);
    return 0;
}
