#include "hs/clinical/Tissue.h"

#include "EnumKey.h"

namespace hs::clinical {

std::string_view toString(Tissue value) {
    switch (value) {
    case Tissue::Myometrium:
        return "myometrium";
    case Tissue::Endometrium:
        return "endometrium";
    case Tissue::Cervix:
        return "cervix";
    case Tissue::Myoma:
        return "myoma";
    case Tissue::Polyp:
        return "polyp";
    }
    return "";
}

std::string_view toString(SurfaceTissue value) {
    switch (value) {
    case SurfaceTissue::Serosa:
        return "serosa";
    case SurfaceTissue::Endometrium:
        return "endometrium";
    case SurfaceTissue::CervicalCanal:
        return "cervical-canal";
    case SurfaceTissue::TubalOstium:
        return "tubal-ostium";
    case SurfaceTissue::Ectocervix:
        return "ectocervix";
    }
    return "";
}

bool fromString(std::string_view key, Tissue& out) {
    return detail::enumFromKey(key, kTissues, out);
}
bool fromString(std::string_view key, SurfaceTissue& out) {
    return detail::enumFromKey(key, kSurfaceTissues, out);
}

} // namespace hs::clinical
