// The statistical shape model reader (HDF5 in statismo's layout), fed through HDF5's in-memory file image so that
// the fuzzer mutates the file structure itself. Property: an error names the source.

#include "FuzzSupport.h"
#include "hs/anatomy/ShapeModel.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const auto model = hs::anatomy::loadShapeModelImage(data, size, "fuzz-model.h5");
    if (!model.ok())
        hs::fuzz::check(model.error().detail.find("fuzz-model.h5") != std::string::npos, "an error names the source",
                        model.error().detail);
    return 0;
}
