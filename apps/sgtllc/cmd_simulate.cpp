// `sgtllc simulate`: placeholder until the simulator lands.
#include "commands.h"

namespace sgtllc::cli {

void addSimulateCommand(CLI::App&) {}

}  // namespace sgtllc::cli
