#pragma once
/// Registration of the subcommands. Each add*Command adds a subcommand to `app` and stores in `exitCode` what its
/// callback returned, so main() can exit with it.

namespace CLI {
class App;
}

namespace hs::cli {

void addInfoCommand(CLI::App& app, int& exitCode);
void addConvertCommand(CLI::App& app, int& exitCode);
void addValidateCommand(CLI::App& app, int& exitCode);
void addTextureCommand(CLI::App& app, int& exitCode);
void addOrganCommand(CLI::App& app, int& exitCode);
void addModelCommand(CLI::App& app, int& exitCode);
void addGenerateCommand(CLI::App& app, int& exitCode);
void addMeshCommand(CLI::App& app, int& exitCode);
void addQualityCommand(CLI::App& app, int& exitCode);
void addPathologyCommand(CLI::App& app, int& exitCode);
void addBatchCommand(CLI::App& app, int& exitCode);

} // namespace hs::cli
