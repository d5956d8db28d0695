// `validate FILE`: checks a case file (later also a scene package) and says what is wrong.
#include "CliCommon.h"
#include "Commands.h"

#include "hs/scene/CaseSpec.h"

#include <CLI/CLI.hpp>

#include <iostream>
#include <memory>

namespace hs::cli {
namespace {

struct ValidateOptions {
    std::string path;
    CommonOptions common;
};

int runValidate(const ValidateOptions& options) {
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

} // namespace

void addValidateCommand(CLI::App& app, int& exitCode) {
    auto options = std::make_shared<ValidateOptions>();
    auto* sub = app.add_subcommand("validate", "Check a case file: every error names the field and its allowed range");
    sub->add_option("FILE", options->path, "case .json")->required();
    sub->add_flag("--json", options->common.json, "print JSON for scripts");
    sub->callback([options, &exitCode] { exitCode = runValidate(*options); });
}

} // namespace hs::cli
