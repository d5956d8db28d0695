#pragma once

#include <hdf5.h>

#include <cstddef>

namespace hs::anatomy::detail {

/// A file access property list that reads an HDF5 file from `size` bytes at `bytes`, read-only, through the
/// project's own file driver. The bytes must outlive every file opened with it. Returns a negative id on failure.
///
/// Why not HDF5's core driver: its files use HDF5 1.10's metadata accumulator, and a damaged file (a B-tree node
/// at address 0 after a failed read) makes the accumulator copy from a null buffer, a crash no check before the call
/// can prevent. This driver declares no features, so HDF5 reads every piece of metadata straight from the bytes,
/// each read checked against the image's end.
hid_t hdf5ImageAccess(const void* bytes, std::size_t size);

} // namespace hs::anatomy::detail
