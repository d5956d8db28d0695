#pragma once
/// Reading a training set from files, for users who build a shape model from their own segmented organs.

#include "hs/anatomy/Cohort.h"
#include "hs/core/Result.h"

#include <string>

namespace hs::anatomy {

/// Reads `paramsCsv` and the meshes it names from `meshDir`.
///
/// The CSV has a header line and one row per organ:
///     file,ageYears,parity,gravidity,heightCm,weightKg,menopausal
///     case-001.vtp,34,1,2,168,61,no
/// `file` is relative to `meshDir` (any surface format hysteroscene reads); `menopausal` is yes/no (or true/false,
/// 1/0). Every mesh must be in correspondence with the first one: the same vertex count and the same triangles.
/// Fails with InvalidInput naming the file, the line and the column, or the mesh that breaks correspondence.
[[nodiscard]] Result<TrainingSet> loadTrainingSet(const std::string& meshDir, const std::string& paramsCsv);

} // namespace hs::anatomy
