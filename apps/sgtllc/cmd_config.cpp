// `sgtllc config`: the configuration in the YAML format that --config reads, or the settings reference.
#include <iostream>
#include <memory>

#include "commands.h"
#include "common.h"
#include "sgtllc/io/config_reference.h"
#include "sgtllc/io/config_yaml.h"

namespace sgtllc::cli {

void addConfigCommand(CLI::App& app) {
  auto path = std::make_shared<std::string>();
  CLI::App* cmd = app.add_subcommand("config", "Print the default configuration (or --config F with F applied)");
  auto markdown = std::make_shared<bool>(false);
  cmd->add_option("--config", *path, "YAML file to check and print in full");
  cmd->add_flag("--markdown", *markdown,
                "Print the settings reference instead: every key, its value, the values it accepts, its meaning "
                "(docs/configuration.md)");
  cmd->callback([path, markdown] {
    const Config config = loadConfigOption(*path, 0);
    std::cout << (*markdown ? io::configReference(config) : io::configToYaml(config));
  });
}

}  // namespace sgtllc::cli
