// `validate PATH`: checks a case file or a scene package folder and says what is wrong.
#include "CliCommon.h"
#include "Commands.h"

#include "hs/scene/CaseSpec.h"
#include "hs/scene/MeshBars.h"
#include "hs/scene/ScenePackage.h"
#include "hs/scene/ScopePassage.h"
#include "hs/scene/ScopeView.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <iostream>
#include <memory>
#include <sstream>
#include <vector>

namespace hs::cli {
namespace {

struct ValidateOptions {
    std::string path;
    double scopeDiameterMm = 2.9; ///< mm, 1-10: the thinnest rigid office hysteroscope by default
    CommonOptions common;
};

/// A named warning: it never changes the exit code of an otherwise valid package.
struct Warning {
    std::string name;
    std::string detail;
};

std::string mm(double value) {
    std::ostringstream out;
    out.precision(2);
    out << std::fixed << value << " mm";
    return out.str();
}

std::string at(const Vec3& p) {
    std::ostringstream out;
    out.precision(1);
    out << std::fixed << "(" << p.x << ", " << p.y << ", " << p.z << " mm)";
    return out.str();
}

std::string where(const scene::PassagePoint& p) {
    std::ostringstream out;
    out.precision(1);
    out << std::fixed << "the " << scene::toString(p.part) << " (" << p.positionMm.x << ", " << p.positionMm.y << ", "
        << p.positionMm.z << " mm, " << p.arcLengthMm << " mm along the route)";
    return out.str();
}

/// The scope passage of a package: the measurement, or why it could not be made.
struct ScopeCheck {
    Result<scene::ScopePassage> passage;
    std::vector<Warning> warnings;
    std::vector<scene::OstiumSight> ostia; ///< each ostium found, and how much of it is in sight
    Vec3 viewpointMm;                      ///< from where: scene::cavityViewpoint
};

/// Below this share of its area in sight from the cavity's middle, an ostium is reported hidden: a funnel seen
/// obliquely shows its near wall and the opening while its lip hides the far wall (about half of it).
constexpr double kOstiumInSight = 0.25;

std::string percent(double fraction) {
    std::ostringstream out;
    out.precision(0);
    out << std::fixed << 100.0 * fraction << " %";
    return out.str();
}

/// "myoma-1 and the wall": what hides an ostium, the most first.
std::string hiddenBy(const scene::OstiumSight& o) {
    std::string text;
    for (std::size_t i = 0; i < o.hiddenBy.size(); ++i)
        text += (i == 0                       ? ""
                 : i + 1 == o.hiddenBy.size() ? " and "
                                              : ", ") +
                (o.hiddenBy[i] == "wall" ? std::string("the wall") : o.hiddenBy[i]);
    return text;
}

/// The tubal ostia as the scope sees them from the cavity's middle: a warning for each one missing (a pathology
/// covers it) or mostly hidden.
void checkOstia(const scene::Scene& sc, const scene::ScopePassage& passage, ScopeCheck& check) {
    check.viewpointMm = scene::cavityViewpoint(sc, passage);
    auto ostia = scene::ostiaInSight(sc, check.viewpointMm);
    if (!ostia.ok()) {
        check.warnings.push_back({"ostium-missing", ostia.error().detail});
        return;
    }
    check.ostia = *ostia;
    for (const char* side : {"left", "right"}) {
        const auto it =
            std::find_if(ostia->begin(), ostia->end(), [&](const scene::OstiumSight& o) { return o.side == side; });
        if (it == ostia->end())
            check.warnings.push_back({"ostium-missing", std::string("the ") + side +
                                                            " tubal ostium has no faces on the visual surface "
                                                            "(a pathology covers it)"});
        else if (it->visibleFraction < kOstiumInSight)
            check.warnings.push_back({"ostium-hidden", std::string("the ") + side + " tubal ostium at " +
                                                           at(it->centreMm) + " is " + percent(it->visibleFraction) +
                                                           " in sight from the cavity's middle " +
                                                           at(check.viewpointMm) + ", hidden by " + hiddenBy(*it)});
    }
}

ScopeCheck checkScope(const scene::Scene& sc, double diameterMm) {
    scene::ScopePassageParams params;
    params.scopeDiameterMm = diameterMm;
    auto landmarks = scene::findScopeLandmarks(sc);
    ScopeCheck check{landmarks.ok() ? scene::checkScopePassage(sc.tets, *landmarks, params)
                                    : Result<scene::ScopePassage>(landmarks.failure()),
                     {},
                     {},
                     {}};
    if (!check.passage.ok()) {
        check.warnings.push_back({"scope-passage-unchecked", check.passage.error().detail});
        return check;
    }
    // The warnings are about the canal (external os to internal os): a cavity narrowed by a pathology is a scene
    // to train in, and is reported without a warning.
    const auto& p = *check.passage;
    if (!p.canalOpen)
        check.warnings.push_back({"scope-passage-closed", "the cervical canal is closed at " + where(p.narrowestCanal) +
                                                              " by about " + mm(p.canalClosedGapMm) + " of tissue"});
    else if (!p.canalPasses)
        check.warnings.push_back({"scope-passage-narrow", "the cervical canal is " + mm(p.narrowestCanal.freeWidthMm) +
                                                              " wide at " + where(p.narrowestCanal) +
                                                              ", narrower than the " + mm(diameterMm) + " scope"});
    if (landmarks->ostiaFound < 2)
        check.warnings.push_back({"scope-passage-landmarks", "one tubal ostium found (a pathology may cover the "
                                                             "other); the route ends at its cornu " +
                                                                 at(landmarks->fundusMm)});
    for (const auto& w : p.warnings)
        check.warnings.push_back({"scope-passage-landmarks", w});
    checkOstia(sc, p, check);
    return check;
}

/// The scope checks, then a warning named by each mesh quality bar the package's report misses.
ScopeCheck checkPackage(const scene::Scene& sc, double diameterMm) {
    ScopeCheck check = checkScope(sc, diameterMm);
    for (const auto& bar : scene::meshBars(sc.quality))
        if (!bar.met)
            check.warnings.push_back({bar.name, bar.detail});
    return check;
}

nlohmann::ordered_json meshBarsJson(const scene::MeshQuality& quality) {
    nlohmann::ordered_json bars = nlohmann::ordered_json::array();
    for (const auto& b : scene::meshBars(quality))
        bars.push_back(
            {{"name", b.name}, {"value", b.value}, {"bar", b.limit}, {"atLeast", b.atLeast}, {"met", b.met}});
    return bars;
}

nlohmann::ordered_json pointJson(const scene::PassagePoint& p) {
    return {{"widthMm", p.freeWidthMm},
            {"part", std::string(scene::toString(p.part))},
            {"positionMm", {p.positionMm.x, p.positionMm.y, p.positionMm.z}},
            {"arcLengthMm", p.arcLengthMm}};
}

nlohmann::ordered_json scopeJson(const ScopeCheck& check, double diameterMm, double straightLengthMm) {
    nlohmann::ordered_json j;
    j["scopeDiameterMm"] = diameterMm;
    j["checked"] = check.passage.ok();
    if (!check.passage.ok())
        return j;
    const auto& p = *check.passage;
    j["passes"] = p.canalPasses;
    j["canal"] = {{"open", p.canalOpen},
                  {"passes", p.canalPasses},
                  {"closedGapMm", p.canalClosedGapMm},
                  {"narrowest", pointJson(p.narrowestCanal)}};
    j["toFundus"] = {{"open", p.open},
                     {"passes", p.ballPasses},
                     {"closedGapMm", p.closedGapMm},
                     {"narrowest", pointJson(p.narrowest)},
                     {"routeLengthMm", p.route.empty() ? 0.0 : p.route.back().arcLengthMm}};
    j["straightStretch"] = {{"lengthMm", straightLengthMm},
                            {"passes", p.straightPasses},
                            {"widthMm", p.straightWidthMm},
                            {"tip", pointJson(p.narrowestStraight)}};
    j["voxelMm"] = p.voxelSizeMm;
    const auto vec = [](const Vec3& v) { return nlohmann::ordered_json::array({v.x, v.y, v.z}); };
    j["landmarksMm"] = {{"externalOs", vec(p.landmarks.externalOsMm)},
                        {"internalOs", vec(p.landmarks.internalOsMm)},
                        {"fundus", vec(p.landmarks.fundusMm)}};
    j["ostiaViewpointMm"] = vec(check.viewpointMm);
    j["ostia"] = nlohmann::ordered_json::array();
    for (const auto& o : check.ostia)
        j["ostia"].push_back({{"side", o.side},
                              {"faces", o.faces},
                              {"inSightPercent", 100.0 * o.visibleFraction},
                              {"hiddenBy", o.hiddenBy},
                              {"centreMm", vec(o.centreMm)}});
    return j;
}

void printScope(const ScopeCheck& check, double diameterMm, double straightLengthMm) {
    if (check.passage.ok()) {
        const auto& p = *check.passage;
        const auto verdict = [](bool passes) { return passes ? "passes" : "does not pass"; };
        std::cout << "scope       " << mm(diameterMm) << " scope through the canal " << verdict(p.canalPasses)
                  << ": narrowest " << mm(p.narrowestCanal.freeWidthMm) << " at " << where(p.narrowestCanal) << '\n'
                  << "scope       to the fundus " << verdict(p.ballPasses) << ": narrowest "
                  << mm(p.narrowest.freeWidthMm) << " at " << where(p.narrowest) << "; route "
                  << mm(p.route.back().arcLengthMm) << '\n'
                  << "scope       straight " << mm(straightLengthMm) << " ahead of the tip: " << mm(p.straightWidthMm)
                  << " free at the least, with the tip at " << where(p.narrowestStraight) << '\n'
                  << "scope       landmarks: external os " << at(p.landmarks.externalOsMm) << ", internal os "
                  << at(p.landmarks.internalOsMm) << ", fundus " << at(p.landmarks.fundusMm) << '\n';
        for (const auto& o : check.ostia)
            std::cout << "ostium      " << o.side << " at " << at(o.centreMm) << ": " << percent(o.visibleFraction)
                      << " in sight from the cavity's middle " << at(check.viewpointMm) << " (" << o.faces << " faces)"
                      << (o.hiddenBy.empty() ? "" : ", the rest hidden by " + hiddenBy(o)) << '\n';
    }
    for (const auto& w : check.warnings)
        std::cout << "warning     " << w.name << ": " << w.detail << '\n';
}

int runValidateCase(const ValidateOptions& options) {
    auto spec = scene::loadCase(options.path);
    if (options.common.json) {
        nlohmann::ordered_json j;
        j["file"] = options.path;
        j["kind"] = "case";
        j["valid"] = spec.ok();
        if (!spec.ok()) {
            j["error"] = {{"code", std::string(errorCodeKey(spec.error().code))}, {"detail", spec.error().detail}};
        }
        printJson(std::cout, j);
        return spec.ok() ? kExitOk : exitCodeFor(spec.error());
    }
    if (!spec.ok())
        return reportError("validate", spec.error());
    std::cout << "valid: " << options.path << " (case)\n";
    for (const auto& line : scene::describe(*spec))
        std::cout << line << '\n';
    return kExitOk;
}

/// A package folder (its manifest.json, or a zipped package): every path, size and checksum, then every file parsed.
int runValidatePackage(const ValidateOptions& options, const std::string& folder) {
    auto manifest = scene::verifyScenePackage(folder);
    Result<scene::Scene> scene =
        manifest.ok() ? scene::readScenePackage(folder) : Result<scene::Scene>(manifest.failure());
    if (options.common.json) {
        nlohmann::ordered_json j;
        j["file"] = options.path;
        j["kind"] = "scene-package";
        j["valid"] = scene.ok();
        if (manifest.ok()) {
            j["schemaVersion"] = manifest->schemaVersion;
            j["toolVersion"] = manifest->toolVersion;
            j["files"] = manifest->files.size();
        }
        if (scene.ok()) {
            j["tets"] = scene->tets.tetCount();
            j["simulationTets"] = scene->simulation ? scene->simulation->tets.tetCount() : 0;
            j["regions"] = scene->regions.size();
            j["labels"] = scene->labels.size();
            const auto scope = checkPackage(*scene, options.scopeDiameterMm);
            j["meshBars"] = meshBarsJson(scene->quality);
            j["scopePassage"] = scopeJson(scope, options.scopeDiameterMm, scene::ScopePassageParams{}.straightLengthMm);
            j["warnings"] = nlohmann::ordered_json::array();
            for (const auto& w : scope.warnings)
                j["warnings"].push_back({{"name", w.name}, {"detail", w.detail}});
        } else {
            j["error"] = {{"code", std::string(errorCodeKey(scene.error().code))}, {"detail", scene.error().detail}};
        }
        printJson(std::cout, j);
        return scene.ok() ? kExitOk : exitCodeFor(scene.error());
    }
    if (!scene.ok())
        return reportError("validate", scene.error());
    std::int64_t bytes = 0;
    for (const auto& f : manifest->files)
        bytes += f.bytes;
    std::cout << "valid: " << folder << " (scene package, schema " << manifest->schemaVersion << ", written by "
              << manifest->toolVersion << ")\n"
              << "files       " << manifest->files.size() << " plus manifest.json, " << bytes
              << " bytes, every SHA-256 checked\n"
              << "tets        " << scene->tets.tetCount() << " tetrahedra, " << scene->tets.vertexCount() << " points\n"
              << "surface     " << scene->surface.mesh.faceCount() << " triangles\n";
    if (scene->simulation)
        std::cout << "simulation  " << scene->simulation->tets.tetCount() << " tetrahedra, "
                  << scene->simulation->tets.vertexCount() << " points (simulation.vtu)\n";
    else
        std::cout << "simulation  none: a package of schema version 1 cannot be simulated (regenerate it)\n";
    for (const auto& m : scene->materials)
        std::cout << "material    " << m.name << " (" << clinical::toString(m.tissue) << "): E "
                  << m.material.youngsModulusKpa << " kPa, nu " << m.material.poissonRatio << ", "
                  << m.material.densityKgPerM3 << " kg/m^3\n";
    std::cout << "labels      " << scene->labels.size() << '\n'
              << "hydrometra  " << scene->hydrometra.cavityVolumeMl << " mL at " << scene->hydrometra.pressureKpa
              << " kPa\n";
    const auto bars = scene::meshBars(scene->quality);
    std::cout << "mesh        "
              << std::count_if(bars.begin(), bars.end(), [](const scene::MeshBar& b) { return b.met; }) << " of "
              << bars.size() << " quality bars met (report.json)\n";
    printScope(checkPackage(*scene, options.scopeDiameterMm), options.scopeDiameterMm,
               scene::ScopePassageParams{}.straightLengthMm);
    return kExitOk;
}

int runValidate(const ValidateOptions& options) {
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::path path(options.path);
    std::string extension = path.extension().string();
    for (char& c : extension)
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (fs::is_directory(path, ec) || extension == ".zip")
        return runValidatePackage(options, options.path);
    if (path.filename() == std::string(scene::kManifestName))
        return runValidatePackage(options, path.parent_path().empty() ? "." : path.parent_path().string());
    return runValidateCase(options);
}

} // namespace

void addValidateCommand(CLI::App& app, int& exitCode) {
    auto options = std::make_shared<ValidateOptions>();
    auto* sub = app.add_subcommand("validate", "Check a case file (every error names the field and its allowed range) "
                                               "or a scene package folder (paths, sizes, checksums, contents)");
    sub->add_option("PATH", options->path,
                    "case .json, or a scene package folder, its manifest.json or a zipped package (.zip)")
        ->required();
    sub->add_option("--scope-diameter", options->scopeDiameterMm,
                    "scene packages: rigid hysteroscope diameter in mm whose passage from the external os to the "
                    "fundus is checked (a warning when it does not fit); default 2.9")
        ->check(CLI::Range(1.0, 10.0));
    sub->add_flag("--json", options->common.json, "print JSON for scripts");
    sub->callback([options, &exitCode] { exitCode = runValidate(*options); });
}

} // namespace hs::cli
