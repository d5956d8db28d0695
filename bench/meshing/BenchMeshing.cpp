// bench_meshing: quality and speed of the particle mesher against TetGen, CGAL Mesh_3 and Gmsh HXT.
//
//   bench_meshing [--data DIR] [--sizes 5000,50000] [--methods particle,tetgen,cgal,gmsh] [--surfaces a.off,b.obj]
//                 [--threads N] [--seed S]
//
// For each good test surface in DIR (default: the shared data folder configured at build time), then for two shapes
// generated here (disc-40x3: a thin plate 40 mm across and 3 mm thick with a sharp rim; shell-ellipsoid: a closed
// ellipsoidal shell with a 4 mm wall around a cavity, one surface of two components as a hollow organ is given to
// the mesher), and each size, it meshes with every method at the edge length the particle mesher derives for that
// vertex count, and prints one row per run. Time excludes the quality measurement (done the same way for every
// method). --surfaces selects by file or shape name.
#include "MeshingTestShapes.h"

#include "hs/core/RegionModel.h"
#include "hs/io/MeshIO.h"
#include "hs/meshing/BaselineMeshers.h"
#include "hs/meshing/ParticleMesher.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <numeric>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

namespace fs = std::filesystem;
using namespace hs;
using namespace hs::meshing;

namespace {

struct Options {
    std::string data = HS_SHARED_DATA_DIR;
    std::vector<long> sizes{5000, 50000};
    std::vector<std::string> methods{"particle", "tetgen", "cgal", "gmsh"};
    std::vector<std::string> surfaces;
    int threads = 2;
    std::uint64_t seed = 1;
    bool verbose = false;
};

std::vector<std::string> split(const std::string& s) {
    std::vector<std::string> out;
    std::stringstream ss(s);
    std::string item;
    while (std::getline(ss, item, ','))
        if (!item.empty())
            out.push_back(item);
    return out;
}

bool has(const std::vector<std::string>& v, const std::string& x) {
    for (const auto& s : v)
        if (s == x)
            return true;
    return false;
}

struct Row {
    std::string surface, method;
    long target = 0;
    bool ok = false;
    std::string error;
    double seconds = 0.0;
    QualityReport q;
};

double meshingSeconds(const MeshResult& r) {
    double t = 0.0;
    for (const auto& s : r.timings.steps)
        if (s.name != "quality")
            t += s.seconds;
    return t;
}

bool gmshAvailable() {
    return std::system("gmsh --version > /dev/null 2>&1") == 0;
}

/// The face-connected components of `s`, largest bounding box first (the outside of a hollow body, then its
/// cavities), each with its own vertices.
std::vector<SurfaceMesh> components(const SurfaceMesh& s) {
    std::vector<std::size_t> parent(s.points.size());
    std::iota(parent.begin(), parent.end(), std::size_t{0});
    auto find = [&](std::size_t v) {
        while (parent[v] != v)
            v = parent[v] = parent[parent[v]];
        return v;
    };
    for (const Triangle& t : s.triangles)
        for (int k = 1; k < 3; ++k)
            parent[find(std::size_t(t[std::size_t(k)]))] = find(std::size_t(t[0]));
    std::vector<std::size_t> rootOf(s.points.size(), SIZE_MAX);
    std::vector<SurfaceMesh> parts;
    std::vector<std::vector<std::int32_t>> newIndex;
    for (const Triangle& t : s.triangles) {
        const std::size_t root = find(std::size_t(t[0]));
        if (rootOf[root] == SIZE_MAX) {
            rootOf[root] = parts.size();
            parts.emplace_back();
            newIndex.emplace_back(s.points.size(), -1);
        }
        SurfaceMesh& part = parts[rootOf[root]];
        auto& index = newIndex[rootOf[root]];
        Triangle out{};
        for (std::size_t k = 0; k < 3; ++k) {
            const auto v = std::size_t(t[k]);
            if (index[v] < 0) {
                index[v] = std::int32_t(part.points.size());
                part.points.push_back(s.points[v]);
            }
            out[k] = index[v];
        }
        part.triangles.push_back(out);
    }
    auto diagonal = [](const SurfaceMesh& m) {
        Vec3 lo = m.points.front(), hi = m.points.front();
        for (const Vec3& p : m.points) {
            lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
            hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
        }
        return norm(hi - lo);
    };
    std::stable_sort(parts.begin(), parts.end(),
                     [&](const SurfaceMesh& a, const SurfaceMesh& b) { return diagonal(a) > diagonal(b); });
    return parts;
}

Row runGmsh(const RegionModel& body, double edge, const Options& opt) {
    Row row;
    row.method = "gmsh-hxt";
    const fs::path dir = fs::temp_directory_path() / ("hs-bench-gmsh-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    const std::string geo = (dir / "body.geo").string(), msh = (dir / "body.msh").string();
    // One STL and one surface loop per component of the outline: the first bounds the volume, the others (the
    // cavities of a hollow body) are holes in it, so Gmsh meshes the wall only.
    const std::vector<SurfaceMesh> parts = components(body.surfaces[0].surface);
    std::string merges, loops;
    for (std::size_t i = 0; i < parts.size(); ++i) {
        const std::string name = "surface" + std::to_string(i + 1) + ".stl";
        if (auto st = io::writeSurface(parts[i], (dir / name).string()); !st.ok()) {
            row.error = st.error().message();
            return row;
        }
        merges +=
            "Merge \"" + name + "\";\nSurface Loop(" + std::to_string(i + 1) + ") = {" + std::to_string(i + 1) + "};\n";
        loops += (i > 0 ? ", " : "") + std::to_string(i + 1);
    }
    {
        std::ofstream g(geo);
        g << merges << "Volume(1) = {" << loops << "};\nPhysical Volume(0) = {1};\n"
          << "Mesh.MeshSizeMin = " << edge << ";\nMesh.MeshSizeMax = " << edge << ";\n";
    }
    const std::string cmd = "cd '" + dir.string() + "' && gmsh -3 -algo hxt -nt " + std::to_string(opt.threads) +
                            " -format msh41 body.geo -o body.msh > gmsh.log 2>&1";
    const auto t0 = std::chrono::steady_clock::now();
    const int rc = std::system(cmd.c_str());
    row.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (rc != 0) {
        row.error = "gmsh failed (see " + (dir / "gmsh.log").string() + ")";
        return row;
    }
    auto mesh = io::readTetMesh(msh);
    if (!mesh.ok()) {
        row.error = mesh.error().message();
        return row;
    }
    row.q = measureQuality(*mesh, &body, opt.threads);
    row.ok = true;
    fs::remove_all(dir);
    return row;
}

void printHeader() {
    std::printf("%-22s %7s %-9s %8s %9s %8s %6s %7s %7s %9s %8s %9s %9s\n", "surface", "target", "method", "vertices",
                "tets", "time[s]", "meanRR", "minDih", "slivers", "Haus[%]", "Vol[%]", "t/TetGen", "t/Gmsh");
}

void printRow(const Row& r, double tetgenSeconds, double gmshSeconds) {
    if (!r.ok) {
        std::printf("%-22s %7ld %-9s  failed: %s\n", r.surface.c_str(), r.target, r.method.c_str(), r.error.c_str());
        return;
    }
    char tg[32] = "-", gm[32] = "-";
    if (tetgenSeconds > 0.0)
        std::snprintf(tg, sizeof tg, "%.2f", r.seconds / tetgenSeconds);
    if (gmshSeconds > 0.0)
        std::snprintf(gm, sizeof gm, "%.2f", r.seconds / gmshSeconds);
    std::printf("%-22s %7ld %-9s %8zu %9zu %8.2f %6.3f %7.1f %7zu %9.3f %8.3f %9s %9s\n", r.surface.c_str(), r.target,
                r.method.c_str(), r.q.vertexCount, r.q.tetCount, r.seconds, r.q.meanRadiusRatio, r.q.minDihedralDeg,
                r.q.sliverCount, 100.0 * r.q.hausdorffRelative, 100.0 * r.q.volumeError, tg, gm);
    std::fflush(stdout);
}

} // namespace

int main(int argc, char** argv) {
    Options opt;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto next = [&]() -> std::string { return i + 1 < argc ? argv[++i] : ""; };
        if (a == "--data")
            opt.data = next();
        else if (a == "--sizes") {
            opt.sizes.clear();
            for (const auto& s : split(next()))
                opt.sizes.push_back(std::stol(s));
        } else if (a == "--methods")
            opt.methods = split(next());
        else if (a == "--surfaces")
            opt.surfaces = split(next());
        else if (a == "--threads")
            opt.threads = std::stoi(next());
        else if (a == "--seed")
            opt.seed = std::stoull(next());
        else if (a == "--verbose")
            opt.verbose = true;
        else {
            std::cerr << "usage: bench_meshing [--data DIR] [--sizes N,...] [--methods particle,tetgen,cgal,gmsh] "
                         "[--surfaces FILE,...] [--threads N] [--seed S] [--verbose]\n";
            return 2;
        }
    }
    std::vector<fs::path> files;
    const fs::path meshes = fs::path(opt.data) / "meshes";
    if (fs::is_directory(meshes))
        for (const auto& e : fs::directory_iterator(meshes)) {
            const std::string ext = e.path().extension().string();
            if (e.is_regular_file() && (ext == ".off" || ext == ".obj") &&
                (opt.surfaces.empty() || has(opt.surfaces, e.path().filename().string())))
                files.push_back(e.path());
        }
    std::sort(files.begin(), files.end());
    const std::vector<std::pair<std::string, SurfaceMesh (*)()>> shapes{
        {"disc-40x3", [] { return test::thinDisc(40.0, 3.0, 0.6); }},
        {"shell-ellipsoid",
         [] {
             return test::hollowEllipsoid({30.0, 22.0, 18.0}, 4.0, 5);
         }},
    };
    std::size_t shapeCount = 0;
    for (const auto& shape : shapes)
        shapeCount += opt.surfaces.empty() || has(opt.surfaces, shape.first);
    if (files.empty() && shapeCount == 0) {
        std::cerr << "bench_meshing: no surfaces in " << meshes << " and no generated shape selected\n";
        return 1;
    }
    const bool gmsh = has(opt.methods, "gmsh") && gmshAvailable();
    std::printf("bench_meshing: %zu surfaces, %zu generated shapes, threads %d, seed %llu%s\n", files.size(),
                shapeCount, opt.threads, static_cast<unsigned long long>(opt.seed),
                gmsh ? ", gmsh found" : ", gmsh not found");
    printHeader();
    std::vector<std::pair<std::string, RegionModel>> bodies;
    for (const fs::path& file : files) {
        auto surface = io::readSurface(file.string());
        if (!surface.ok()) {
            std::printf("%-22s read failed: %s\n", file.filename().c_str(), surface.error().message().c_str());
            continue;
        }
        bodies.emplace_back(file.filename().string(),
                            RegionModel::fromSurfaces({*surface}, {file.filename().string()}));
    }
    for (const auto& [name, make] : shapes)
        if (opt.surfaces.empty() || has(opt.surfaces, name))
            bodies.emplace_back(name, RegionModel::fromSurfaces({make()}, {name}));
    for (const auto& [bodyName, body] : bodies) {
        for (long size : opt.sizes) {
            MeshParams params;
            params.targetVertices = size;
            params.seed = opt.seed;
            params.threads = opt.threads;
            auto edge = resolveEdgeLength(body, params);
            if (!edge.ok()) {
                std::printf("%-22s %7ld failed: %s\n", bodyName.c_str(), size, edge.error().message().c_str());
                continue;
            }
            MeshParams fixed = params;
            fixed.targetEdgeLength = *edge;
            std::vector<Row> rows;
            double tetgenSeconds = 0.0, gmshSeconds = 0.0;
            for (const std::string& name : opt.methods) {
                Row row;
                if (name == "gmsh") {
                    if (!gmsh)
                        continue;
                    row = runGmsh(body, *edge, opt);
                    if (row.ok)
                        gmshSeconds = row.seconds;
                } else {
                    const auto method = parseMethod(name);
                    if (!method || !methodAvailable(*method))
                        continue;
                    row.method = name;
                    auto r = meshWith(*method, body, fixed);
                    if (r.ok()) {
                        row.ok = true;
                        row.seconds = meshingSeconds(*r);
                        row.q = r->quality;
                        if (opt.verbose) {
                            std::printf("  %s steps:", name.c_str());
                            for (const auto& st : r->timings.steps) {
                                std::printf(" %s %.3f", st.name.c_str(), st.seconds);
                                for (const auto& [k, v] : st.counts)
                                    std::printf(" (%s %lld)", k.c_str(), static_cast<long long>(v));
                            }
                            std::printf("\n");
                        }
                        if (*method == MeshMethod::TetGen)
                            tetgenSeconds = row.seconds;
                    } else {
                        row.error = r.error().message();
                    }
                }
                row.surface = bodyName;
                row.target = size;
                rows.push_back(row);
            }
            for (const Row& r : rows)
                printRow(r, r.method == "particle" ? tetgenSeconds : 0.0, r.method == "particle" ? gmshSeconds : 0.0);
        }
    }
    return 0;
}
