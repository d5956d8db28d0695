#pragma once
/// FIGO leiomyoma classification (PALM-COEIN; docs/references.md [Munro2011]) and the Lasmar (STEPW) score for
/// hysteroscopic myomectomy (Lasmar et al. 2005; docs/references.md [Lasmar2005]).

#include <optional>
#include <string>
#include <string_view>

namespace hs::clinical {

/// A FIGO type 0..8, or a hybrid "X-Y" (X: relation to the endometrium, 1..3; Y: relation to the serosa, 5..6),
/// the convention of Munro et al., Int J Gynaecol Obstet 2011.
struct FigoType {
    int type = 0;     ///< 0..8; for a hybrid, the endometrial part; -1: not classified (a polyp's descriptors)
    int serosal = -1; ///< hybrid only: the serosal part; -1 when not a hybrid

    constexpr bool isHybrid() const { return serosal >= 0; }
    /// True for 0..8 and for hybrids X-Y with X in 1..3 and Y in 5..6.
    constexpr bool isValid() const {
        return isHybrid() ? (type >= 1 && type <= 3 && serosal >= 5 && serosal <= 6) : (type >= 0 && type <= 8);
    }
    /// Only types 0-2 are resectable hysteroscopically [Munro2011]; a hybrid counts by its endometrial part.
    constexpr bool isHysteroscopicallyResectable() const { return type >= 0 && type <= 2; }
    /// "2" or "2-5"; "-" when not classified.
    std::string toString() const;
    /// Parses "N" or "X-Y" (digits only, no spaces); std::nullopt on anything else. Does not check isValid().
    static std::optional<FigoType> parse(std::string_view text);
};
bool operator==(const FigoType& a, const FigoType& b);
bool operator!=(const FigoType& a, const FigoType& b);

/// The FIGO definition of a plain type 0..8 [Munro2011], e.g. "submucosal, >= 50 % intramural"; "" otherwise.
std::string_view figoDefinition(int type);

/// Lasmar (STEPW) score components; each -1 when not computed (the pathology stage computes them for myomas).
struct LasmarScore {
    int size = -1;        ///< <= 20 mm 0, 20-50 mm 1, > 50 mm 2
    int topography = -1;  ///< lower 0, middle 1, upper third 2
    int extension = -1;   ///< base <= 1/3 of the wall 0, 1/3-2/3 1, > 2/3 2
    int penetration = -1; ///< intramural 0 % 0, < 50 % 1, >= 50 % 2
    int wall = -1;        ///< lateral wall 1, else 0
    bool complete() const { return size >= 0 && topography >= 0 && extension >= 0 && penetration >= 0 && wall >= 0; }
    /// 0..9 when complete(), else -1.
    int total() const { return complete() ? size + topography + extension + penetration + wall : -1; }
};

} // namespace hs::clinical
