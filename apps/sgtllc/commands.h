// The sgtllc subcommands. Each registers itself on the app and runs from its callback.
#pragma once

#include <CLI/CLI.hpp>

namespace sgtllc::cli {

void addPairCommand(CLI::App& app);
void addLabelCommand(CLI::App& app);
void addRunCommand(CLI::App& app);
void addConfigCommand(CLI::App& app);
void addEvalCommand(CLI::App& app);
void addOptimizeCommand(CLI::App& app);
void addSimulateCommand(CLI::App& app);
void addLocalizeCommand(CLI::App& app);
void addMapCommand(CLI::App& app);
void addRepeatabilityCommand(CLI::App& app);

}  // namespace sgtllc::cli
