#pragma once
/// The merge stage: organ + grown pathologies -> one multi-region body (RegionModel) with contact labels
/// (Sierra et al. 2004, sec. 2.1: "a merging step joins pathology and organ; contact labels are kept").
///
/// The body's outline is the organ united with each pathology wrapped in a thin cover of wall tissue (the
/// endometrium draped over a submucosal myoma or a polyp, the serosa over a subserosal one); every pathology is a
/// nested region inside it. So the pathologies' surfaces are the interfaces, shared by the pathology and the wall, and
/// never touch the outline (RegionModel's rule).

#include "hs/core/Progress.h"
#include "hs/core/RegionModel.h"
#include "hs/core/Result.h"
#include "hs/core/Timings.h"
#include "hs/pathology/Pathology.h"

#include <cstdint>
#include <string>
#include <vector>

namespace hs::merge {

/// Values of the face label "contact" on a pathology's surface: what lies across it.
enum class Contact : std::int32_t {
    Myometrium = 1,  ///< inside the wall (intramural part; a polyp's base)
    Endometrium = 2, ///< covered by the endometrium draped into the cavity
    Serosa = 3,      ///< covered by the serosa (subserosal part)
};
/// Face label on pathology surfaces (Contact values).
inline constexpr const char* kContactLabel = "contact";
/// Face label on the outline: 1 + index of the pathology a face is draped over, 0 elsewhere.
inline constexpr const char* kPathologyLabel = "pathology";
/// The outline keeps the organ's "tissue" face label (hs/anatomy/UterusGenerator.h); draped faces take the tissue
/// of the organ surface they replace.

struct MergeParams {
    /// mm of wall tissue draped over the parts of a pathology outside the wall (an alpha wrap at this offset, which
    /// cannot fold). A mesh whose edge is longer than this gives most of that layer to the pathology's region.
    double coverMm = 0.8;
    bool validate = true; ///< checks the result with validate(RegionModel) (self-intersections, crossings)
};

struct MergeResult {
    RegionModel body;     ///< surfaces[0]: outline, region 0 (wall); surfaces[i + 1]: pathology i, region i + 1
    StageTimings timings; ///< cover, union, labels, validate
    std::vector<std::string> warnings;
};

/// Fails with InvalidInput when a surface is open or self-intersecting, or the result breaks RegionModel's rules
/// (naming the pathology), BackendFailure when CGAL's corefinement fails, Cancelled on request.
[[nodiscard]] Result<MergeResult> mergeBody(const pathology::PathologyResult& grown, const MergeParams& params = {},
                                            Progress& progress = Progress::none());

} // namespace hs::merge
