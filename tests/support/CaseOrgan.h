#pragma once
/// The organ a case grows its pathologies on (the organ stage of hs::generate): for tests that place or grow
/// pathologies on the default case's organ without generating the whole scene. Header-only; the test links
/// hs::generate.

#include "hs/anatomy/ShapeModel.h"
#include "hs/generate/CaseStages.h"

#include <string>

namespace hs::test {

/// The organ stage of `spec` (its shape model, read relative to `caseFile`).
inline Result<generate::OrganInstance> caseOrgan(const scene::CaseSpec& spec, const std::string& caseFile) {
    auto request = generate::organRequestFor(spec, caseFile);
    if (!request)
        return request.failure();
    auto model = anatomy::loadShapeModel(generate::modelPathFor(spec, caseFile));
    if (!model)
        return model.failure();
    return generate::makeOrgan(*model, *request);
}

} // namespace hs::test
