#include "hs/core/LabelTransfer.h"

#include <gtest/gtest.h>

namespace {

/// A unit square in z = 0 split into two triangles, labelled 7 (lower right) and 9 (upper left).
hs::SurfaceMesh labelledSquare() {
    hs::SurfaceMesh m;
    m.points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    m.triangles = {{0, 1, 2}, {0, 2, 3}};
    m.faceLabels["side"] = {7, 9};
    return m;
}

} // namespace

TEST(LabelTransfer, EachFaceTakesTheLabelOfTheNearestSourceFace) {
    const auto from = labelledSquare();
    hs::SurfaceMesh to;
    // Small triangles slightly above the square: one inside each source triangle, one far away.
    to.points = {{0.8, 0.1, 0.05}, {0.9, 0.1, 0.05}, {0.9, 0.2, 0.05}, {0.1, 0.8, 0.05}, {0.2, 0.9, 0.05},
                 {0.1, 0.9, 0.05}, {5, 5, 5},        {5.1, 5, 5},      {5, 5.1, 5}};
    to.triangles = {{0, 1, 2}, {3, 4, 5}, {6, 7, 8}};
    ASSERT_TRUE(hs::transferFaceLabels(from, to, {"side"}, 0.5, -1).ok());
    EXPECT_EQ(to.faceLabels.at("side"), (std::vector<std::int32_t>{7, 9, -1}));
}

TEST(LabelTransfer, RefusesAMissingLabelAndABadDistance) {
    const auto from = labelledSquare();
    auto to = labelledSquare();
    EXPECT_FALSE(hs::transferFaceLabels(from, to, {"nothing"}, 1.0).ok());
    EXPECT_FALSE(hs::transferFaceLabels(from, to, {"side"}, 0.0).ok());
}
