#pragma once
/// The clinical description of a pathology, as the case file states it and the pathology stage grows it
/// (Sierra et al. 2004, sec. 2.1; docs/references.md [Sierra2004]). One definition shared by the stages, the case
/// format and the scene.
///
/// Each enumeration has a stable lower-case key: toString() / fromString(). The keys are written into case.json
/// and scene packages, so they never change.

#include <array>
#include <string_view>

namespace hs::clinical {

enum class PathologyKind { Myoma, Polyp };
enum class GrowthModel {
    CellularAutomaton, ///< "ca": voxel automaton; myomas only [Sierra2004]
    Skeleton,          ///< "skeleton": object skeleton + revolved contours; myomas and polyps [Sierra2004]
    Particles,         ///< "particles": dividing cells that push each other; myomas and polyps [Sierra2004]
};
enum class UterineLocation {
    Fundal,
    Anterior,
    Posterior,
    LeftLateral,
    RightLateral,
    CornualLeft,
    CornualRight,
    Isthmic,
    Cervical, ///< myomas of FIGO type 8 only
};
enum class PolypAttachment { Sessile, Pedunculated };

constexpr std::array<PathologyKind, 2> kPathologyKinds{PathologyKind::Myoma, PathologyKind::Polyp};
constexpr std::array<GrowthModel, 3> kGrowthModels{GrowthModel::CellularAutomaton, GrowthModel::Skeleton,
                                                   GrowthModel::Particles};
constexpr std::array<UterineLocation, 9> kUterineLocations{
    UterineLocation::Fundal,       UterineLocation::Anterior,     UterineLocation::Posterior,
    UterineLocation::LeftLateral,  UterineLocation::RightLateral, UterineLocation::CornualLeft,
    UterineLocation::CornualRight, UterineLocation::Isthmic,      UterineLocation::Cervical};
constexpr std::array<PolypAttachment, 2> kPolypAttachments{PolypAttachment::Sessile, PolypAttachment::Pedunculated};

std::string_view toString(PathologyKind value);   ///< "myoma", "polyp"
std::string_view toString(GrowthModel value);     ///< "ca", "skeleton", "particles"
std::string_view toString(UterineLocation value); ///< "fundal", ..., "left-lateral", "cornual-left", ...
std::string_view toString(PolypAttachment value); ///< "sessile", "pedunculated"
/// Sets `out` and returns true when `key` is one of the keys above.
bool fromString(std::string_view key, PathologyKind& out);
bool fromString(std::string_view key, GrowthModel& out);
bool fromString(std::string_view key, UterineLocation& out);
bool fromString(std::string_view key, PolypAttachment& out);

} // namespace hs::clinical
