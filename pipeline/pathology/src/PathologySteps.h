#pragma once
/// The steps of the pathology stage (growPathologies): the types they share and the functions the driver calls.

#include "Organ.h"
#include "Shapes.h"

#include "hs/pathology/Pathology.h"

#include <string>
#include <vector>

namespace hs::pathology::detail {

constexpr double kSinkMm = 1.5; ///< a stalk's root lies this deep in the wall

std::string fmt(double v, int digits = 1);
std::string fmt(const Vec3& v);

/// The wall chord through the placement: endometrium point, serosa point, direction from cavity into the wall.
struct Seat {
    Vec3 endometrium, serosa, intoWall;
    double wallMm = 0.0;
};

struct Planned {
    const PathologyRequest* request = nullptr;
    ShapeSpec spec;
    Seat seat;
    bool fromSerosa = false; ///< types 5-7: grows from the serosa side
    SurfaceMesh surface;
};

/// "myoma 'id'": how messages name a request.
std::string who(const PathologyRequest& r);

// Validation.cpp
Status checkRequest(const PathologyRequest& r);
Status checkSize(const PathologyRequest& r, const OrganInfo& info);
/// Fails naming both when they come within `gap` mm of each other or one lies inside the other.
Status checkOverlap(const Planned& first, const Planned& second, double gap);
Status checkOverlaps(const std::vector<Planned>& all, double gap);

// Placement.cpp
Result<Seat> seatFrom(const PathologyRequest& r, const OrganInfo& info, double tol, std::vector<std::string>& notes);
/// The seats on the endometrium within `reachMm` of `nominal` whose wall faces within `turnDeg` of it (the same
/// wall), nearest first (ties by face order, so the list is deterministic).
std::vector<Seat> nearbySeats(const OrganInfo& info, const Seat& nominal, double reachMm, double turnDeg);
Result<ShapeSpec> planShape(const PathologyRequest& r, const OrganInfo& info, const Seat& seat,
                            const PathologyParams& params, const std::vector<const SurfaceMesh*>& earlier,
                            bool& fromSerosa);
/// The tubal ostium the shape planned by `spec` for `r` covers or hides ("right", "left"), empty when it keeps both
/// free: its head and its foot stay kOstiumClearMm beyond their radii from each labelled ostium's centre, and, on a
/// lateral or cornual wall, its head as far from the sight line from the cavity's middle to that side's ostium.
std::string ostiumCoveredBy(const PathologyRequest& r, const OrganInfo& info, const ShapeSpec& spec);
/// The same for a grown shape: a point of it within kOstiumClearMm of an ostium's centre, or, on a lateral or cornual
/// wall, within kOstiumSightClearMm of the sight line to that side's ostium or a face across it.
std::string ostiumHiddenByShape(const PathologyRequest& r, const OrganInfo& info, const SurfaceMesh& shape);
/// The seats a pathology placed by location may slide to off an ostium: the endometrium within the cavity's length of
/// `nominal` whose wall faces within 80 degrees of it, nearest first; and that reach in mm.
std::vector<Seat> seatsOffOstia(const OrganInfo& info, const Seat& nominal);
double ostiumSlideReachMm(const OrganInfo& info);
/// The seat to grow a pathology placed by location at first: `nominal` when the shape planned there keeps both ostia
/// free (ostiumCoveredBy), else the nearest of seatsOffOstia whose planned shape does; `nominal` when none does or the
/// placement is a point (a case may put a pathology on an ostium on purpose).
Seat plannedOffOstia(const PathologyRequest& r, const OrganInfo& info, const Seat& nominal,
                     const PathologyParams& params, const std::vector<const SurfaceMesh*>& earlier);

// Stalk.cpp
/// The stalk's direction: the way it hangs (stalkDirection), or, when that runs into a pathology planned before
/// it, the nearest direction (tilted in 15 degree steps, still leaving the wall) whose head keeps `gap` from it.
/// Among the clear directions of a tilt, the one that stays closest to the cavity's plane (least anteroposterior):
/// the cavity is flat, so a head tilted towards the anterior or posterior wall would stand in it.
Vec3 freeStalkDirection(const OrganInfo& info, const Seat& seat, double reach, double radius, double stalkRadius,
                        double gap, const std::vector<const SurfaceMesh*>& earlier);

// Fit.cpp
/// Scales so the measured size equals the request: about the centroid, or, for stalked shapes, about the planned
/// centre of the head when it grows (a head grown smaller than planned has its foot further out by the difference,
/// and growing about its centre brings the foot back to the planned stalk length; its root sinks deeper into the
/// wall; scaled about the planned foot, the particle model's stalks measured 9.4-10.7 mm where 7-8 mm were asked)
/// and about the stalk's root when it shrinks (the root stays in the wall); a sessile polyp about the endometrium
/// point it sits on (about its sunk root, a shrinking head sank into the wall: 22-39 % of it measured intramural).
void scaleToSize(SurfaceMesh& mesh, const ShapeSpec& spec, double sizeMm);
/// Moves the shape along the wall chord until its depth matches the FIGO type, measured against the planes of
/// the wall at the seat (the local slab, so the far wall of a narrow cavity does not count): intramural fraction
/// 0.25 (types 1, 6) or 0.75 (types 2, 5), or a gap of half the contact tolerance to the endometrium (type 3).
void fitDepth(SurfaceMesh& mesh, const SurfaceMesh& organ, const PathologyRequest& r, const Seat& seat,
              const PathologyParams& params);

// MassEffect.cpp
/// First: a pathology's pushes, its stalk aimed anew; Again: once all are placed, the pushes that keep a myoma clear of
/// the endometrium and of the serosa, on the organ the later ones left.
enum class AdaptRound { First, Again };
/// Applies pathology `which`'s pushes to the organ and to every other pathology (they sit in the moving tissue).
Status adaptOrgan(SurfaceMesh& organ, std::vector<Planned>& all, std::size_t which, const PathologyParams& params,
                  AdaptRound round = AdaptRound::First);
/// The pushes leave a pocket with flat faces and square corners around a head on a stalk, where it meets the wall it
/// opens from (each push is a smooth map of space, but the walls they move by different amounts meet at a crease).
/// The cavity's walls collapse onto a mass instead: the displacement of the moved cavity-side vertices near such a
/// head (within 3 radii + 10 mm of its centre), and two rings around them, is averaged with their neighbours'
/// (Jacobi, kPocketRounds rounds, half weight), each vertex held where its next step would bring it closer than the
/// clearance + kPocketSlackMm to a pathology (tracked with a slack, so distances are only recomputed when a vertex
/// may have used its slack up; steps are shorter than that distance, so none jumps through a surface), and vertices
/// inside a pathology or already that close to one (the wall it stands in) held throughout. Kept only when the organ
/// still does not intersect itself.
void roundPockets(SurfaceMesh& adapted, const SurfaceMesh& original, const OrganInfo& info,
                  const std::vector<Planned>& plans, const PathologyParams& params);

} // namespace hs::pathology::detail
