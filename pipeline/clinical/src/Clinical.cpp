#include "hs/clinical/Clinical.h"

#include "EnumKey.h"

namespace hs::clinical {

std::string_view toString(PathologyKind value) {
    switch (value) {
    case PathologyKind::Myoma:
        return "myoma";
    case PathologyKind::Polyp:
        return "polyp";
    }
    return "";
}

std::string_view toString(GrowthModel value) {
    switch (value) {
    case GrowthModel::CellularAutomaton:
        return "ca";
    case GrowthModel::Skeleton:
        return "skeleton";
    case GrowthModel::Particles:
        return "particles";
    }
    return "";
}

std::string_view toString(UterineLocation value) {
    switch (value) {
    case UterineLocation::Fundal:
        return "fundal";
    case UterineLocation::Anterior:
        return "anterior";
    case UterineLocation::Posterior:
        return "posterior";
    case UterineLocation::LeftLateral:
        return "left-lateral";
    case UterineLocation::RightLateral:
        return "right-lateral";
    case UterineLocation::CornualLeft:
        return "cornual-left";
    case UterineLocation::CornualRight:
        return "cornual-right";
    case UterineLocation::Isthmic:
        return "isthmic";
    case UterineLocation::Cervical:
        return "cervical";
    }
    return "";
}

std::string_view toString(PolypAttachment value) {
    switch (value) {
    case PolypAttachment::Sessile:
        return "sessile";
    case PolypAttachment::Pedunculated:
        return "pedunculated";
    }
    return "";
}

bool fromString(std::string_view key, PathologyKind& out) {
    return detail::enumFromKey(key, kPathologyKinds, out);
}
bool fromString(std::string_view key, GrowthModel& out) {
    return detail::enumFromKey(key, kGrowthModels, out);
}
bool fromString(std::string_view key, UterineLocation& out) {
    return detail::enumFromKey(key, kUterineLocations, out);
}
bool fromString(std::string_view key, PolypAttachment& out) {
    return detail::enumFromKey(key, kPolypAttachments, out);
}

} // namespace hs::clinical
