// hysteroscene-cli: everything the workstation does, headless.
#include "CliCommon.h"
#include "Commands.h"

#include <CLI/CLI.hpp>

#include <iostream>

int main(int argc, char** argv) {
    CLI::App app{"hysteroscene-cli: scenario generation for hysteroscopy training simulators, headless"};
    app.name("hysteroscene-cli");
    app.set_version_flag("--version", std::string("hysteroscene-cli ") + HS_VERSION);
    app.require_subcommand(1);
    app.footer("Exit codes: 0 ok, 2 usage, 3 invalid input, 4 failed. See docs/cli.md.");

    int exitCode = hs::cli::kExitOk;
    hs::cli::addInfoCommand(app, exitCode);
    hs::cli::addConvertCommand(app, exitCode);
    hs::cli::addValidateCommand(app, exitCode);
    hs::cli::addTextureCommand(app, exitCode);
    hs::cli::addOrganCommand(app, exitCode);
    hs::cli::addModelCommand(app, exitCode);
    hs::cli::addGenerateCommand(app, exitCode);
    hs::cli::addMeshCommand(app, exitCode);
    hs::cli::addQualityCommand(app, exitCode);
    hs::cli::addPathologyCommand(app, exitCode);
    hs::cli::addBatchCommand(app, exitCode);

    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        app.exit(e);
        return hs::cli::kExitUsage;
    }
    return exitCode;
}
