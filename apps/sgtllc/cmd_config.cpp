// `sgtllc config`: the configuration in the YAML format that --config reads.
#include <iostream>
#include <memory>

#include "commands.h"
#include "common.h"
#include "sgtllc/io/config_yaml.h"

namespace sgtllc::cli {

void addConfigCommand(CLI::App& app) {
  auto path = std::make_shared<std::string>();
  CLI::App* cmd = app.add_subcommand("config", "Print the default configuration (or --config F with F applied)");
  cmd->add_option("--config", *path, "YAML file to check and print in full");
  cmd->callback([path] { std::cout << io::configToYaml(loadConfigOption(*path, 0)); });
}

}  // namespace sgtllc::cli
