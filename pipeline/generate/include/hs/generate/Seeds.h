#pragma once
/// The seed plan: every random number of a scene derives from the case seed through the one table of
/// hs/core/Streams.h; this header turns a case seed into its stage and variant seeds.
///
/// Each stage draws from its own stream, `Rng::deriveSeed(caseSeed, stream)`, so changing one stage's use of
/// randomness leaves the others alone. Variants of a case (`generate --variants N`) get seeds from a separate range
/// of stream indices. deriveSeed is injective in its index for a fixed seed (the index is multiplied by an odd
/// constant modulo 2^64, xor-ed with the seed and passed through SplitMix64's bijective finaliser), so a variant's
/// seed can never equal one of the base case's stage seeds: the two index ranges are disjoint.

#include "hs/core/Streams.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace hs::generate {

/// The stages of the chain, in the order they run.
enum class Stage { Organ, Pathology, Merge, Meshing, Tissue, Texture, Scene };
inline constexpr int kStageCount = 7;

/// "organ", "pathology", "merge", "meshing", "tissue", "texture", "scene".
std::string_view toString(Stage stage);
/// Sets `out` and returns true when `key` is one of the keys above.
bool fromString(std::string_view key, Stage& out);

/// A named random stream of the case seed.
enum class Stream : std::uint64_t {
    Pathology = streams::kPathology, ///< placement and growth of every pathology (one sub-stream per pathology)
    Meshing = streams::kMeshing,     ///< particle seeding, relaxation, sliver repair
    Texture = streams::kTexture,     ///< exemplar synthesis, vessels
    Material = streams::kMaterial,   ///< per-tet heterogeneity of Young's modulus
};

/// The organ stage uses the case seed itself (the shape model's sample); every other stage its stream.
std::uint64_t organSeed(std::uint64_t caseSeed);
std::uint64_t streamSeed(std::uint64_t caseSeed, Stream stream);

/// First stream index of variant seeds: far above every stage stream, so the ranges cannot meet.
inline constexpr std::uint64_t kVariantStreamBase = streams::kVariantBase;

/// The seed of variant `index` of a case whose seed is `baseSeed` (`Rng::deriveSeed(baseSeed, 2^62 + index)`).
std::uint64_t variantSeed(std::uint64_t baseSeed, std::size_t index);
/// The folder name of variant `index` among several ("variant-007"): the CLI's and the workstation's exports agree.
std::string variantFolderName(std::size_t index);
/// The seed of variant `index` of `count` variants: the base seed itself when there is only one.
std::uint64_t exportSeed(std::uint64_t baseSeed, std::size_t index, std::size_t count);

} // namespace hs::generate
