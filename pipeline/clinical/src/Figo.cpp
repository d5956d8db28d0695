#include "hs/clinical/Figo.h"

namespace hs::clinical {
namespace {

bool isDigit(char c) {
    return c >= '0' && c <= '9';
}

} // namespace

std::string FigoType::toString() const {
    if (type < 0)
        return "-";
    std::string text = std::to_string(type);
    if (isHybrid())
        text += "-" + std::to_string(serosal);
    return text;
}

std::optional<FigoType> FigoType::parse(std::string_view text) {
    // One digit, or digit-digit: every valid FIGO type is a single digit, so longer numbers are rejected here.
    if (text.size() == 1 && isDigit(text[0]))
        return FigoType{text[0] - '0', -1};
    if (text.size() == 3 && isDigit(text[0]) && text[1] == '-' && isDigit(text[2]))
        return FigoType{text[0] - '0', text[2] - '0'};
    return std::nullopt;
}

bool operator==(const FigoType& a, const FigoType& b) {
    return a.type == b.type && a.serosal == b.serosal;
}
bool operator!=(const FigoType& a, const FigoType& b) {
    return !(a == b);
}

std::string_view figoDefinition(int type) {
    switch (type) {
    case 0:
        return "pedunculated intracavitary";
    case 1:
        return "submucosal, < 50 % intramural";
    case 2:
        return "submucosal, >= 50 % intramural";
    case 3:
        return "contacts the endometrium, 100 % intramural";
    case 4:
        return "intramural";
    case 5:
        return "subserosal, >= 50 % intramural";
    case 6:
        return "subserosal, < 50 % intramural";
    case 7:
        return "subserosal pedunculated";
    case 8:
        return "other (cervical, parasitic)";
    default:
        return "";
    }
}

} // namespace hs::clinical
