#pragma once
/// The readers and writers of each format, dispatched from MeshIO.cpp. Every reader gets a path and the limits and
/// returns a mesh that has passed hs::validate; every writer gets a validated mesh and a temporary path to write.

#include "hs/core/Result.h"
#include "hs/core/SurfaceMesh.h"
#include "hs/core/TetMesh.h"
#include "hs/io/MeshIO.h"

#include <array>
#include <string>
#include <vector>

namespace hs::io::detail {

Result<SurfaceMesh> readObj(const std::string& path, const ReadLimits& limits);
Status writeObj(const SurfaceMesh& mesh, const std::string& tmpPath);

Result<SurfaceMesh> readOff(const std::string& path, const ReadLimits& limits);
Status writeOff(const SurfaceMesh& mesh, const std::string& tmpPath);

Result<SurfaceMesh> readPly(const std::string& path, const ReadLimits& limits);
Status writePly(const SurfaceMesh& mesh, const std::string& tmpPath, bool binary);

Result<SurfaceMesh> readStl(const std::string& path, const ReadLimits& limits);
Status writeStl(const SurfaceMesh& mesh, const std::string& tmpPath, bool binary);

/// `arrays`: when set, also the floating-point point arrays (see readSurfaceWithArrays).
Result<SurfaceMesh> readVtp(const std::string& path, const ReadLimits& limits, PointArrays* arrays = nullptr);
/// Writes the options' binary/compress choice, texture coordinates, normals and point arrays.
Status writeVtp(const SurfaceMesh& mesh, const std::string& tmpPath, const WriteOptions& options);

/// A VTU with tetrahedra gives a TetMesh; one with only surface cells a SurfaceMesh.
Result<AnyMesh> readVtu(const std::string& path, const ReadLimits& limits);
Status writeVtu(const TetMesh& mesh, const std::string& tmpPath, const WriteOptions& options);
Status writeVtuSurface(const SurfaceMesh& mesh, const std::string& tmpPath, const WriteOptions& options);

Result<TetMesh> readGmsh(const std::string& path, const ReadLimits& limits);
Status writeGmsh(const TetMesh& mesh, const std::string& tmpPath);

Result<TetMesh> readMedit(const std::string& path, const ReadLimits& limits);
Status writeMedit(const TetMesh& mesh, const std::string& tmpPath);

} // namespace hs::io::detail
