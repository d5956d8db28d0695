#pragma once
/// The package's JSON documents (private to hs::scene): scene.json (regions, materials, hydrometra, clinical
/// descriptors, tool versions), labels.json (named index sets) and report.json (mesh quality, counts, warnings).
/// Writers are deterministic (fixed member order, shortest round-trip numbers, 2-space indent, final newline);
/// readers take untrusted text and fail with InvalidInput naming the file and the JSON path.

#include "hs/core/Result.h"
#include "hs/scene/Scene.h"

#include <string>
#include <string_view>

namespace hs::scene::detail {

std::string sceneJson(const Scene& scene);
std::string labelsJson(const Scene& scene);
std::string reportJson(const Scene& scene);

/// Fill the matching members of `scene`.
[[nodiscard]] Status parseSceneJson(std::string_view text, const std::string& name, Scene& scene);
[[nodiscard]] Status parseLabelsJson(std::string_view text, const std::string& name, Scene& scene);
[[nodiscard]] Status parseReportJson(std::string_view text, const std::string& name, Scene& scene);

} // namespace hs::scene::detail
