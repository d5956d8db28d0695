#include "hs/generate/Seeds.h"

#include "hs/core/Rng.h"

#include <array>
#include <cstdio>

namespace hs::generate {
namespace {

constexpr std::array<std::string_view, kStageCount> kStageKeys{"organ",  "pathology", "merge", "meshing",
                                                               "tissue", "texture",   "scene"};

} // namespace

std::string_view toString(Stage stage) {
    return kStageKeys[static_cast<std::size_t>(stage)];
}

bool fromString(std::string_view key, Stage& out) {
    for (std::size_t i = 0; i < kStageKeys.size(); ++i)
        if (kStageKeys[i] == key) {
            out = static_cast<Stage>(i);
            return true;
        }
    return false;
}

std::uint64_t organSeed(std::uint64_t caseSeed) {
    return caseSeed;
}

std::uint64_t streamSeed(std::uint64_t caseSeed, Stream stream) {
    return Rng::deriveSeed(caseSeed, static_cast<std::uint64_t>(stream));
}

std::uint64_t variantSeed(std::uint64_t baseSeed, std::size_t index) {
    return Rng::deriveSeed(baseSeed, kVariantStreamBase + static_cast<std::uint64_t>(index));
}

std::string variantFolderName(std::size_t index) {
    char name[32];
    std::snprintf(name, sizeof name, "variant-%03zu", index);
    return name;
}

std::uint64_t exportSeed(std::uint64_t baseSeed, std::size_t index, std::size_t count) {
    return count == 1 ? baseSeed : variantSeed(baseSeed, index);
}

} // namespace hs::generate
