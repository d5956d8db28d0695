// Resection with a loop electrode: the wire's sweep through the tets, their removal from the solver and what the cut
// took (docs/simulator.md, "Cutting").
#include "hs/sim/Resection.h"

#include "hs/core/TetEmbedding.h"
#include "hs/core/TriangleGeometry.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>

namespace hs::sim {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kMlPerMm3 = 1e-3;
/// A sample counts as inside a tet with barycentric coordinates down to this (a sample on a shared face or edge
/// takes every tet there: the wire has a thickness).
constexpr double kInsideSlack = 1e-9;

using Clock = std::chrono::steady_clock;

struct Box {
    Vec3 lo{std::numeric_limits<double>::max(), std::numeric_limits<double>::max(), std::numeric_limits<double>::max()};
    Vec3 hi{-std::numeric_limits<double>::max(), -std::numeric_limits<double>::max(),
            -std::numeric_limits<double>::max()};
    void add(const Vec3& p) {
        for (int d = 0; d < 3; ++d) {
            lo[d] = std::min(lo[d], p[d]);
            hi[d] = std::max(hi[d], p[d]);
        }
    }
    bool overlaps(const Box& o) const {
        for (int d = 0; d < 3; ++d)
            if (hi[d] < o.lo[d] || o.hi[d] < lo[d])
                return false;
        return true;
    }
    bool contains(const Vec3& p) const {
        for (int d = 0; d < 3; ++d)
            if (p[d] < lo[d] || p[d] > hi[d])
                return false;
        return true;
    }
};

/// Whether `p` lies in the tet (a, b, c, d), either orientation (a tet the tissue has turned inside out still takes
/// the wire).
bool insideTet(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
    const std::array<double, 4> w = barycentric(a, b, c, d, p);
    if (w[0] == 0.0 && w[1] == 0.0 && w[2] == 0.0 && w[3] == 0.0)
        return false; // flat
    return w[0] >= -kInsideSlack && w[1] >= -kInsideSlack && w[2] >= -kInsideSlack && w[3] >= -kInsideSlack;
}

} // namespace

std::vector<Vec3> loopWire(const LoopElectrode& loop, const Vec3& centreMm, const Vec3& axis, const Vec3& down) {
    const double r = 0.5 * loop.widthMm;
    const Vec3 side = normalized(cross(axis, down));
    const Vec3 d = normalized(down);
    const double sample = std::max(1e-3, loop.sampleMm);
    const auto pieces = static_cast<std::size_t>(std::max(2.0, std::ceil(kPi * r / sample)));
    std::vector<Vec3> wire;
    wire.reserve(pieces + 1);
    for (std::size_t k = 0; k <= pieces; ++k) {
        const double a = kPi * static_cast<double>(k) / static_cast<double>(pieces); // 0: one end, pi: the other
        wire.push_back(centreMm + side * (r * std::cos(a)) + d * (r * std::sin(a)));
    }
    return wire;
}

std::vector<Vec3> jawWire(const JawInstrument& jaws, const Vec3& hingeMm, const Vec3& axis, const Vec3& down,
                          double openDeg) {
    const Vec3 forward = normalized(axis);
    const Vec3 d = normalized(down);
    const double a = std::clamp(openDeg, 0.0, 89.0) * kPi / 180.0;
    const auto pieces = static_cast<std::size_t>(
        std::max(1.0, std::ceil(std::max(0.0, jaws.jawLengthMm) / std::max(1e-3, jaws.sampleMm))));
    const Vec3 up = (forward * std::cos(a) - d * std::sin(a)) * jaws.jawLengthMm;
    const Vec3 low = (forward * std::cos(a) + d * std::sin(a)) * jaws.jawLengthMm;
    std::vector<Vec3> wire;
    wire.reserve(2 * pieces + 1);
    for (std::size_t k = pieces; k > 0; --k)
        wire.push_back(hingeMm + up * (static_cast<double>(k) / static_cast<double>(pieces)));
    wire.push_back(hingeMm);
    for (std::size_t k = 1; k <= pieces; ++k)
        wire.push_back(hingeMm + low * (static_cast<double>(k) / static_cast<double>(pieces)));
    return wire;
}

Result<Resection> Resection::make(const scene::Scene& scene, const TetMesh& restMm,
                                  const std::vector<Triangle>& boundary, const std::vector<char>& faceCavity) {
    if (faceCavity.size() != boundary.size())
        return fail(ErrorCode::InvalidInput, "resection: one cavity flag per boundary face");
    HS_TRY(validate(restMm));
    Resection r;
    const std::size_t tets = restMm.tetCount();
    r.m_restMm = restMm.points;
    // Each tet's tissue and pathology, from its scene region.
    std::map<std::int32_t, std::pair<clinical::Tissue, std::int32_t>> byRegion;
    for (const scene::SceneRegion& region : scene.regions) {
        std::int32_t pathology = -1;
        for (std::size_t k = 0; k < scene.clinical.pathologies.size(); ++k)
            if (scene.clinical.pathologies[k].regionId == region.id)
                pathology = static_cast<std::int32_t>(k);
        byRegion[region.id] = {region.tissue, pathology};
    }
    r.m_tetTissue.assign(tets, clinical::Tissue::Myometrium);
    r.m_tetPathology.assign(tets, -1);
    r.m_tetVolumeMl.assign(tets, 0.0);
    r.m_totals.pathologyMl.assign(scene.clinical.pathologies.size(), 0.0);
    r.m_totals.pathologyRemovedMl.assign(scene.clinical.pathologies.size(), 0.0);
    for (std::size_t t = 0; t < tets; ++t) {
        const auto it = byRegion.find(restMm.regionOf(t));
        if (it == byRegion.end())
            return fail(ErrorCode::InvalidInput, "resection: tet " + std::to_string(t) + " has region " +
                                                     std::to_string(restMm.regionOf(t)) +
                                                     ", which the scene does not list");
        r.m_tetTissue[t] = it->second.first;
        r.m_tetPathology[t] = it->second.second;
        r.m_tetVolumeMl[t] = std::abs(signedVolume(restMm, t)) * kMlPerMm3;
        if (r.m_tetPathology[t] >= 0)
            r.m_totals.pathologyMl[static_cast<std::size_t>(r.m_tetPathology[t])] += r.m_tetVolumeMl[t];
    }
    // The serosa: boundary faces off the cavity; a tet with one of them opens the wall when it goes.
    std::map<std::array<std::int32_t, 3>, char> outerFace;
    for (std::size_t f = 0; f < boundary.size(); ++f)
        outerFace[sortedFace(boundary[f][0], boundary[f][1], boundary[f][2])] = faceCavity[f] ? 0 : 1;
    r.m_tetOnSerosa.assign(tets, 0);
    for (std::size_t t = 0; t < tets; ++t)
        for (const auto& face : kTetFacePoints) {
            const Tet& k = restMm.tets[t];
            const auto it =
                outerFace.find(sortedFace(k[static_cast<std::size_t>(face[0])], k[static_cast<std::size_t>(face[1])],
                                          k[static_cast<std::size_t>(face[2])]));
            if (it != outerFace.end() && it->second)
                r.m_tetOnSerosa[t] = 1;
        }
    // Each point's depth below the cavity's surface at rest, and each tet's deepest point.
    std::vector<double> pointDepth(restMm.points.size(), 0.0);
    for (std::size_t i = 0; i < restMm.points.size(); ++i) {
        double best = std::numeric_limits<double>::max();
        for (std::size_t f = 0; f < boundary.size(); ++f) {
            if (!faceCavity[f])
                continue;
            const Triangle& t = boundary[f];
            best =
                std::min(best, closestPointOnTriangle(restMm.points[i], restMm.points[static_cast<std::size_t>(t[0])],
                                                      restMm.points[static_cast<std::size_t>(t[1])],
                                                      restMm.points[static_cast<std::size_t>(t[2])])
                                   .distance2);
        }
        pointDepth[i] = best < std::numeric_limits<double>::max() ? std::sqrt(best) : 0.0;
    }
    r.m_tetDepthMm.assign(tets, 0.0);
    for (std::size_t t = 0; t < tets; ++t)
        for (const std::int32_t p : restMm.tets[t])
            r.m_tetDepthMm[t] = std::max(r.m_tetDepthMm[t], pointDepth[static_cast<std::size_t>(p)]);
    return r;
}

std::vector<std::size_t> Resection::sweptTets(const mechanics::CorotationalFem& fem, double sampleMm,
                                              const std::vector<Vec3>& wireFromMm,
                                              const std::vector<Vec3>& wireToMm) const {
    std::vector<std::size_t> hit;
    const std::size_t n = std::min(wireFromMm.size(), wireToMm.size());
    if (n == 0 || fem.tetCount() != m_tetTissue.size())
        return hit;
    // The swept wire's samples: each point's path cut into pieces no longer than a sample, the wire between them the
    // same.
    const double sample = std::max(1e-3, sampleMm);
    double move = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        if (!isFinite(wireFromMm[i]) || !isFinite(wireToMm[i]))
            return hit;
        move = std::max(move, norm(wireToMm[i] - wireFromMm[i]));
    }
    const auto steps = static_cast<std::size_t>(std::ceil(move / sample));
    std::vector<Vec3> samples;
    for (std::size_t s = 0; s <= steps; ++s) {
        const double u = steps == 0 ? 1.0 : static_cast<double>(s) / static_cast<double>(steps);
        for (std::size_t i = 0; i < n; ++i) {
            const Vec3 a = wireFromMm[i] + (wireToMm[i] - wireFromMm[i]) * u;
            samples.push_back(a);
            if (i + 1 < n) {
                const Vec3 b = wireFromMm[i + 1] + (wireToMm[i + 1] - wireFromMm[i + 1]) * u;
                const auto pieces = static_cast<std::size_t>(std::ceil(norm(b - a) / sample));
                for (std::size_t k = 1; k < pieces; ++k)
                    samples.push_back(a + (b - a) * (static_cast<double>(k) / static_cast<double>(pieces)));
            }
        }
    }
    Box swept;
    for (const Vec3& p : samples)
        swept.add(p);
    // The live tets whose box meets the sweep's, then the samples inside each.
    const std::vector<Vec3>& xm = fem.positionsM();
    const auto at = [&xm](std::int32_t p) { return xm[static_cast<std::size_t>(p)] * 1e3; };
    const std::vector<Tet>& tets = fem.tets();
    for (std::size_t t = 0; t < tets.size(); ++t) {
        if (fem.tetRemoved(t))
            continue;
        const Vec3 a = at(tets[t][0]), b = at(tets[t][1]), c = at(tets[t][2]), d = at(tets[t][3]);
        Box box;
        box.add(a);
        box.add(b);
        box.add(c);
        box.add(d);
        if (!box.overlaps(swept))
            continue;
        for (const Vec3& p : samples)
            if (box.contains(p) && insideTet(p, a, b, c, d)) {
                hit.push_back(t);
                break;
            }
    }
    return hit;
}

CutEvent Resection::cut(mechanics::UterusModel& model, double sampleMm, const std::vector<Vec3>& wireFromMm,
                        const std::vector<Vec3>& wireToMm) {
    const auto started = Clock::now();
    CutEvent event;
    const std::vector<std::size_t> hit = sweptTets(model.fem, sampleMm, wireFromMm, wireToMm);
    if (hit.empty()) {
        event.topologyMs = std::chrono::duration<double, std::milli>(Clock::now() - started).count();
        return event;
    }
    event.sweptTets = hit.size();
    std::vector<Vec3> pointsMm(model.fem.positionsM().size());
    for (std::size_t i = 0; i < pointsMm.size(); ++i)
        pointsMm[i] = model.fem.positionsM()[i] * 1e3;
    mechanics::CorotationalFem::Removal removal =
        model.cutTets(hit, pointsMm, mechanics::CorotationalFem::Refactor::Downdate);
    event.removed = std::move(removal.removed);
    event.chips = std::move(removal.chips);
    for (const std::size_t t : event.removed) {
        const std::int32_t pathology = m_tetPathology[t];
        if (pathology >= 0) {
            event.pathologyMl += m_tetVolumeMl[t];
            m_totals.pathologyRemovedMl[static_cast<std::size_t>(pathology)] += m_tetVolumeMl[t];
        } else {
            event.healthyMl += m_tetVolumeMl[t];
        }
        if (m_tetTissue[t] == clinical::Tissue::Myometrium || m_tetTissue[t] == clinical::Tissue::Cervix)
            event.deepestMyometriumMm = std::max(event.deepestMyometriumMm, m_tetDepthMm[t]);
        if (m_tetOnSerosa[t])
            event.perforation = true;
    }
    ++m_totals.events;
    m_totals.removedTets += event.removed.size();
    m_totals.chips += event.chips.size();
    m_totals.healthyMl += event.healthyMl;
    m_totals.deepestMyometriumMm = std::max(m_totals.deepestMyometriumMm, event.deepestMyometriumMm);
    if (event.perforation)
        ++m_totals.perforations;
    event.topologyMs = std::chrono::duration<double, std::milli>(Clock::now() - started).count();
    return event;
}

} // namespace hs::sim
