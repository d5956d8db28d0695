#include "hs/texture/Vessels.h"

#include "hs/core/PointGrid.h"
#include "hs/core/Rng.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>
#include <vector>

namespace hs::texture {
namespace {

/// The faces of one class and where they meet other classes.
struct ClassSurface {
    std::vector<std::int32_t> faces;
    std::vector<double> cumulativeArea;
    std::vector<std::int32_t> componentOfFace; ///< per entry of `faces`
    std::vector<double> componentArea;
    std::vector<std::vector<std::int32_t>> border; ///< per component: vertices shared with another class
};

std::int32_t findRoot(std::vector<std::int32_t>& parent, std::int32_t v) {
    while (parent[static_cast<std::size_t>(v)] != v) {
        parent[static_cast<std::size_t>(v)] = parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(v)])];
        v = parent[static_cast<std::size_t>(v)];
    }
    return v;
}

ClassSurface classSurface(const SurfaceMesh& mesh, const std::vector<Appearance>& faceClass, Appearance cls) {
    ClassSurface cs;
    std::vector<std::int32_t> parent(mesh.points.size());
    std::iota(parent.begin(), parent.end(), 0);
    std::vector<std::uint8_t> inClass(mesh.points.size(), 0), inOther(mesh.points.size(), 0);
    double total = 0.0;
    for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
        const auto& t = mesh.triangles[f];
        if (faceClass[f] != cls) {
            for (std::int32_t v : t)
                inOther[static_cast<std::size_t>(v)] = 1;
            continue;
        }
        cs.faces.push_back(static_cast<std::int32_t>(f));
        const Vec3& a = mesh.points[static_cast<std::size_t>(t[0])];
        total += 0.5 * norm(cross(mesh.points[static_cast<std::size_t>(t[1])] - a,
                                  mesh.points[static_cast<std::size_t>(t[2])] - a));
        cs.cumulativeArea.push_back(total);
        for (std::int32_t v : t)
            inClass[static_cast<std::size_t>(v)] = 1;
        for (std::size_t k = 1; k < 3; ++k) {
            const std::int32_t ra = findRoot(parent, t[0]), rb = findRoot(parent, t[k]);
            if (ra != rb)
                parent[static_cast<std::size_t>(std::max(ra, rb))] = std::min(ra, rb);
        }
    }
    std::vector<std::int32_t> compOfRoot(mesh.points.size(), -1);
    double previous = 0.0;
    for (std::size_t i = 0; i < cs.faces.size(); ++i) {
        const std::int32_t r = findRoot(parent, mesh.triangles[static_cast<std::size_t>(cs.faces[i])][0]);
        if (compOfRoot[static_cast<std::size_t>(r)] < 0) {
            compOfRoot[static_cast<std::size_t>(r)] = static_cast<std::int32_t>(cs.componentArea.size());
            cs.componentArea.push_back(0.0);
        }
        const std::int32_t c = compOfRoot[static_cast<std::size_t>(r)];
        cs.componentOfFace.push_back(c);
        cs.componentArea[static_cast<std::size_t>(c)] += cs.cumulativeArea[i] - previous;
        previous = cs.cumulativeArea[i];
    }
    cs.border.resize(cs.componentArea.size());
    for (std::size_t v = 0; v < mesh.points.size(); ++v)
        if (inClass[v] && inOther[v])
            cs.border[static_cast<std::size_t>(
                          compOfRoot[static_cast<std::size_t>(findRoot(parent, static_cast<std::int32_t>(v)))])]
                .push_back(static_cast<std::int32_t>(v));
    return cs;
}

/// A uniformly distributed point on the class's faces; `component` receives its component.
Vec3 samplePoint(const SurfaceMesh& mesh, const ClassSurface& cs, Rng& rng, std::int32_t* component = nullptr) {
    const double target = rng.uniform() * cs.cumulativeArea.back();
    const auto i = static_cast<std::size_t>(
        std::upper_bound(cs.cumulativeArea.begin(), cs.cumulativeArea.end(), target) - cs.cumulativeArea.begin());
    const std::size_t idx = std::min(i, cs.faces.size() - 1);
    if (component)
        *component = cs.componentOfFace[idx];
    const auto& t = mesh.triangles[static_cast<std::size_t>(cs.faces[idx])];
    const double r1 = std::sqrt(rng.uniform()), r2 = rng.uniform();
    return mesh.points[static_cast<std::size_t>(t[0])] * (1 - r1) +
           mesh.points[static_cast<std::size_t>(t[1])] * (r1 * (1 - r2)) +
           mesh.points[static_cast<std::size_t>(t[2])] * (r1 * r2);
}

struct Node {
    Vec3 p;
    Vec3 dir;
    std::int32_t parent = -1;
};

/// Where the surface is near p: the nearest vertex's normal, and p moved onto its tangent plane.
struct SurfaceSnap {
    const SurfaceMesh& mesh;
    const std::vector<Vec3>& normals;
    const PointGrid& grid;
    double radius;
    Bounds bounds; ///< of the surface's points

    bool snap(Vec3& p, Vec3& n) const {
        std::int32_t v = grid.nearest(p, radius, mesh.points);
        if (v < 0)
            v = grid.nearest(p, 4 * radius, mesh.points);
        if (v < 0)
            return false;
        n = normals[static_cast<std::size_t>(v)];
        p -= n * dot(p - mesh.points[static_cast<std::size_t>(v)], n);
        return true;
    }
};

std::vector<Vec3> roots(const SurfaceMesh& mesh, const ClassSurface& cs, Appearance cls, const VesselClassParams& cp,
                        Rng& rng) {
    std::vector<Vec3> out;
    for (std::size_t c = 0; c < cs.componentArea.size(); ++c) {
        const auto& border = cs.border[c];
        const int count = cls == Appearance::Polyp
                              ? 1
                              : std::max(1, static_cast<int>(std::lround(cs.componentArea[c] * cp.rootsPerMm2)));
        if ((cls == Appearance::Polyp || cls == Appearance::Myoma) && !border.empty()) {
            if (cls == Appearance::Polyp) {
                // The stalk: the border vertex nearest the centre of the border ring.
                Vec3 centre;
                for (std::int32_t v : border)
                    centre += mesh.points[static_cast<std::size_t>(v)];
                centre = centre / static_cast<double>(border.size());
                std::int32_t best = border[0];
                for (std::int32_t v : border)
                    if (distance(mesh.points[static_cast<std::size_t>(v)], centre) <
                        distance(mesh.points[static_cast<std::size_t>(best)], centre))
                        best = v;
                out.push_back(mesh.points[static_cast<std::size_t>(best)]);
            } else { // myoma: vessels enter from the surrounding wall
                for (int i = 0; i < count; ++i)
                    out.push_back(mesh.points[static_cast<std::size_t>(border[rng.below(border.size())])]);
            }
            continue;
        }
        for (int i = 0, tries = 0; i < count && tries < 100 * count; ++tries) {
            std::int32_t comp = -1;
            const Vec3 p = samplePoint(mesh, cs, rng, &comp);
            if (comp == static_cast<std::int32_t>(c)) {
                out.push_back(p);
                ++i;
            }
        }
    }
    return out;
}

/// Space colonisation on the class's faces; returns the nodes.
std::vector<Node> growClass(const SurfaceMesh& mesh, const ClassSurface& cs, Appearance cls,
                            const VesselClassParams& cp, const VesselParams& params, const SurfaceSnap& surface,
                            Rng& rng, Progress& progress, bool& cancelled) {
    std::vector<Node> nodes;
    const double area = cs.cumulativeArea.back();
    const auto attractorCount = static_cast<std::size_t>(std::min(2.0e6, area * cp.attractorsPerMm2));
    std::vector<Vec3> attractors(attractorCount);
    for (auto& a : attractors)
        a = samplePoint(mesh, cs, rng);
    std::vector<std::uint8_t> alive(attractors.size(), 1);
    const PointGrid attractorGrid = PointGrid::of(attractors, cp.influenceMm);

    // Nodes stay on the surface (a node off the grid's box goes to a border cell and is still found).
    PointGrid nodeGrid(surface.bounds, cp.influenceMm, Vec3{}, 1);
    std::vector<Vec3> nodePos;
    const auto addNode = [&](const Node& n) {
        nodeGrid.insert(static_cast<std::int32_t>(nodes.size()), n.p);
        nodes.push_back(n);
        nodePos.push_back(n.p);
    };
    for (Vec3 r : roots(mesh, cs, cls, cp, rng)) {
        Vec3 n;
        surface.snap(r, n);
        addNode({r, Vec3(), -1});
    }
    std::vector<Vec3> pull;
    std::vector<int> pulls;
    for (int iter = 0; iter < params.maxIterations; ++iter) {
        if (progress.cancelled()) {
            cancelled = true;
            return nodes;
        }
        pull.assign(nodes.size(), Vec3());
        pulls.assign(nodes.size(), 0);
        bool any = false;
        for (std::size_t a = 0; a < attractors.size(); ++a) {
            if (!alive[a])
                continue;
            const std::int32_t n = nodeGrid.nearest(attractors[a], cp.influenceMm, nodePos);
            if (n < 0)
                continue;
            pull[static_cast<std::size_t>(n)] += normalized(attractors[a] - nodePos[static_cast<std::size_t>(n)]);
            ++pulls[static_cast<std::size_t>(n)];
            any = true;
        }
        if (!any)
            break;
        const std::size_t before = nodes.size();
        for (std::size_t i = 0; i < before; ++i) {
            if (pulls[i] == 0)
                continue;
            Vec3 dir = normalized(pull[i]);
            const Vec3 wobble = normalized(Vec3(rng.normal(), rng.normal(), rng.normal()));
            dir = normalized(dir + wobble * cp.tortuosity + nodes[i].dir * (0.3 * cp.tortuosity));
            Vec3 p = nodes[i].p + dir * cp.stepMm;
            Vec3 normal;
            if (!surface.snap(p, normal))
                continue;
            bool crowded = false;
            nodeGrid.forEachNear(p, 0.3 * cp.stepMm, [&](std::int32_t id) {
                crowded = crowded || distance(nodePos[static_cast<std::size_t>(id)], p) < 0.3 * cp.stepMm;
            });
            if (crowded)
                continue;
            addNode({p, normalized(p - nodes[i].p), static_cast<std::int32_t>(i)});
            if (static_cast<std::int64_t>(nodes.size()) >= params.maxNodes)
                return nodes;
        }
        if (nodes.size() == before)
            break;
        for (std::size_t i = before; i < nodes.size(); ++i)
            attractorGrid.forEachNear(nodePos[i], cp.killMm, [&](std::int32_t a) {
                if (distance(attractors[static_cast<std::size_t>(a)], nodePos[i]) < cp.killMm)
                    alive[static_cast<std::size_t>(a)] = 0;
            });
    }
    return nodes;
}

} // namespace

std::array<VesselClassParams, kAppearanceCount> VesselParams::defaultVesselClassParams() {
    std::array<VesselClassParams, kAppearanceCount> p{};
    // Endometrium: a fine, dense capillary network, faint.
    p[0] = {0.35, 0.004, 0.5, 2.5, 0.7, 0.022, 0.12, 0.25, 0.45};
    // Myoma: few, large, tortuous vessels coming from the wall over the pale surface.
    p[1] = {0.12, 0.004, 0.7, 5.0, 1.2, 0.045, 0.45, 0.55, 0.85};
    // Polyp: one central vessel from the stalk with thin branches.
    p[2] = {0.10, 0.0, 0.6, 6.0, 1.2, 0.035, 0.30, 0.15, 0.75};
    // Cervical canal: fine branched vessels over the papillae (Mhaskar), sparser and fainter than the endometrium's.
    p[3] = {0.25, 0.004, 0.5, 2.5, 0.7, 0.022, 0.10, 0.25, 0.35};
    return p;
}

Result<VesselNetwork> growVessels(const SurfaceMesh& surface, const std::vector<Appearance>& faceAppearance,
                                  const VesselParams& params, Progress& progress) {
    if (faceAppearance.size() != surface.triangles.size())
        return fail(ErrorCode::InvalidInput, "vessels: " + std::to_string(faceAppearance.size()) +
                                                 " face classes for " + std::to_string(surface.triangles.size()) +
                                                 " faces");
    VesselNetwork network;
    if (surface.triangles.empty())
        return network;
    const std::vector<Vec3> normals = vertexNormals(surface);
    double edgeSum = 0.0;
    for (const auto& t : surface.triangles)
        edgeSum +=
            distance(surface.points[static_cast<std::size_t>(t[0])], surface.points[static_cast<std::size_t>(t[1])]);
    const double meanEdge = std::max(1e-6, edgeSum / static_cast<double>(surface.triangles.size()));
    const PointGrid vertexGrid = PointGrid::of(surface.points, 2.0 * meanEdge);
    Bounds bounds;
    for (const Vec3& p : surface.points)
        bounds.add(p);
    const SurfaceSnap snap{surface, normals, vertexGrid, 2.0 * meanEdge, bounds};

    for (Appearance cls : kAppearances) {
        const auto ci = static_cast<std::size_t>(cls);
        const VesselClassParams& cp = params.perClass[ci];
        const ClassSurface cs = classSurface(surface, faceAppearance, cls);
        if (cs.faces.empty() || cs.cumulativeArea.back() <= 0.0 || cp.attractorsPerMm2 <= 0.0)
            continue;
        Rng rng = Rng(params.seed).derive(ci + 1);
        bool cancelled = false;
        const double part = static_cast<double>(ci);
        Progress::Sub sub = progress.sub(part / 3.0, (part + 1) / 3.0);
        const std::vector<Node> nodes = growClass(surface, cs, cls, cp, params, snap, rng, sub, cancelled);
        if (cancelled)
            return fail(ErrorCode::Cancelled, "vessel growth cancelled");
        // Murray's law from the leaves up (children always come after their parent).
        std::vector<double> cubeSum(nodes.size(), 0.0);
        std::vector<double> radius(nodes.size(), cp.leafRadiusMm);
        for (std::size_t i = nodes.size(); i-- > 0;) {
            if (cubeSum[i] > 0.0)
                radius[i] = std::min(cp.maxRadiusMm, std::cbrt(cubeSum[i]));
            if (nodes[i].parent >= 0)
                cubeSum[static_cast<std::size_t>(nodes[i].parent)] += radius[i] * radius[i] * radius[i];
        }
        for (std::size_t i = 0; i < nodes.size(); ++i) {
            if (nodes[i].parent < 0) {
                ++network.roots[ci];
                continue;
            }
            const auto p = static_cast<std::size_t>(nodes[i].parent);
            network.segments.push_back(
                {nodes[p].p, nodes[i].p, radius[p], radius[i], cls, static_cast<float>(cp.contrast)});
        }
        network.nodes[ci] = static_cast<int>(nodes.size());
        progress.report("texture.vessels", (part + 1) / 3.0);
    }
    return network;
}

} // namespace hs::texture
