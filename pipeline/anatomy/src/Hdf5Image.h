#pragma once

#include <hdf5.h>

#include <cstddef>
#include <string>

namespace hs::anatomy::detail {

/// A file access property list that reads an HDF5 file from `size` bytes at `bytes`, read-only, through the
/// project's own file driver. The bytes must outlive every file opened with it. Returns a negative id on failure.
///
/// Why not HDF5's core driver: its files use HDF5 1.10's metadata accumulator, and a damaged file (a B-tree node
/// at address 0 after a failed read) makes the accumulator copy from a null buffer, a crash no check before the call
/// can prevent. This driver declares no features, so HDF5 reads every piece of metadata straight from the bytes,
/// each read checked against the image's end.
hid_t hdf5ImageAccess(const void* bytes, std::size_t size);

/// What HDF5 1.10 cannot survive in an image, found before HDF5 sees it; empty when nothing is.
///
/// A local heap (a group's name store) keeps its free blocks as a list of offsets. HDF5 1.10 follows the list without
/// looking for a cycle and allocates for every step, so a list that comes back on itself takes all memory (a fuzzed
/// 240 KB model reached 21 GB). Every local heap in the image is found by its signature (HDF5 refuses a heap without
/// one) and its list walked as HDF5 walks it; one that comes back on itself, or sizes of offsets and lengths other
/// than 2, 4 or 8 bytes, is named here.
std::string findHdf5ImageDamage(const void* bytes, std::size_t size);

} // namespace hs::anatomy::detail
