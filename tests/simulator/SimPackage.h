#pragma once
// A scene package for the simulator's tests: the default case with a lighter visual mesh and maps (the simulation
// mesh is the same size as the default package's), generated once per test binary. The default case's polyp sits in
// the right cornu, beside its ostium; here it sits on the posterior wall (where the simulator's figures were first
// measured, when a cornual polyp still covered the ostium).

#include "CaseOrgan.h"
#include "OrganOstia.h"
#include "TestSupport.h"
#include "hs/generate/Generate.h"
#include "hs/scene/ScenePackage.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <optional>
#include <string>

namespace hs::test {

class SimPackage {
public:
    /// The package's folder (generated on first use; a test fails if generation fails).
    static const std::string& folder() {
        static SimPackage package(Variant::PosteriorPolyp);
        return package.m_folder;
    }
    /// The default case with its myoma at the fundus, FIGO 2, 25 mm (seated in the wall, a third of it in the cavity),
    /// and no polyp: the scope meets the myoma head-on.
    static const std::string& fundalMyomaFolder() {
        static SimPackage package(Variant::FundalMyoma);
        return package.m_folder;
    }
    /// The default case with its polyp put on the right tubal ostium on purpose (by a point): the scene has one ostium.
    static const std::string& polypOnTheRightOstiumFolder() {
        static SimPackage package(Variant::PolypOnTheRightOstium);
        return package.m_folder;
    }

private:
    enum class Variant { PosteriorPolyp, FundalMyoma, PolypOnTheRightOstium };
    explicit SimPackage(Variant variant) : m_dir(std::make_unique<TempDir>("hs-sim-package")) {
        const bool fundalMyoma = variant == Variant::FundalMyoma;
        auto spec = scene::loadCase(HS_DEFAULT_CASE_FILE);
        if (!spec) {
            ADD_FAILURE() << spec.error().detail;
            return;
        }
        spec->meshing.targetVertices = 8000;
        std::optional<Vec3> ostium;
        if (variant == Variant::PolypOnTheRightOstium) {
            auto organ = caseOrgan(*spec, HS_DEFAULT_CASE_FILE);
            auto found = organ ? rightOstiumCentre(organ->mesh) : Result<Vec3>(organ.failure());
            if (!found) {
                ADD_FAILURE() << found.error().detail;
                return;
            }
            ostium = *found;
        }
        if (fundalMyoma)
            spec->pathologies.erase(
                std::remove_if(spec->pathologies.begin(), spec->pathologies.end(),
                               [](const scene::PathologySpec& p) { return p.kind == clinical::PathologyKind::Polyp; }),
                spec->pathologies.end());
        for (auto& p : spec->pathologies)
            if (ostium && p.kind == clinical::PathologyKind::Polyp)
                p.placement = clinical::SurfacePlacement{*ostium, {0.0, 0.0, 1.0}};
            else if (ostium)
                continue;
            else if (p.kind == clinical::PathologyKind::Polyp)
                p.placement = clinical::ClinicalPlacement{clinical::UterineLocation::Posterior};
            else if (fundalMyoma && p.kind == clinical::PathologyKind::Myoma) {
                p.placement = clinical::ClinicalPlacement{clinical::UterineLocation::Fundal};
                p.figo = clinical::FigoType{2, -1};
                p.sizeMm = 25.0;
            }
        spec->texture.sizePx = 256;
        generate::GenerateParams params;
        params.caseFile = HS_DEFAULT_CASE_FILE;
        auto generated = generate::generateScene(*spec, params);
        if (!generated) {
            ADD_FAILURE() << generated.error().detail;
            return;
        }
        m_folder = m_dir->file("default");
        auto written = scene::writeScenePackage(*generated->scene, m_folder);
        if (!written)
            ADD_FAILURE() << written.error().detail;
    }
    std::unique_ptr<TempDir> m_dir;
    std::string m_folder;
};

} // namespace hs::test
