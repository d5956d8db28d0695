#include "TestFrames.h"

namespace hs::test {

sim::ScopeFrame testPivot() {
    sim::ScopeFrame f;
    f.pivotMm = {0.0, 0.0, 0.0};
    f.axis = {0.0, 0.0, 1.0};
    f.anterior = {0.0, 1.0, 0.0};
    f.left = {-1.0, 0.0, 0.0};
    return f;
}

std::shared_ptr<const sim::HapticFrame> wallFrame(double wallZ, double stiffnessNPerMm) {
    auto frame = std::make_shared<sim::HapticFrame>();
    frame->pivot = testPivot();
    frame->contactStiffnessNPerMm = stiffnessNPerMm;
    constexpr int kCells = 10;
    constexpr double kSize = 10.0;
    const auto index = [](int i, int j) { return static_cast<std::int32_t>(i * (kCells + 1) + j); };
    for (int i = 0; i <= kCells; ++i)
        for (int j = 0; j <= kCells; ++j)
            frame->pointsMm.push_back({-50.0 + kSize * i, -50.0 + kSize * j, wallZ});
    auto triangles = std::make_shared<std::vector<Triangle>>();
    for (int i = 0; i < kCells; ++i)
        for (int j = 0; j < kCells; ++j) {
            // Wound so that the normal is -z: towards the pivot, the free side.
            triangles->push_back({index(i, j), index(i, j + 1), index(i + 1, j)});
            triangles->push_back({index(i + 1, j), index(i, j + 1), index(i + 1, j + 1)});
        }
    frame->triangles = std::move(triangles);
    return frame;
}

} // namespace hs::test
