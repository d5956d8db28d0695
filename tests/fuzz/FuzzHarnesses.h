#pragma once
/// The table of fuzz harnesses the replay test runs (generated from tests/fuzz/CMakeLists.txt).

#include <cstddef>
#include <cstdint>
#include <vector>

namespace hs::fuzz {

struct Harness {
    const char* name;                                       ///< as in hs_fuzz_harness, e.g. "mesh_obj"
    int (*run)(const std::uint8_t* data, std::size_t size); ///< the harness's LLVMFuzzerTestOneInput
};

const std::vector<Harness>& harnesses();

} // namespace hs::fuzz
