// YAML configuration (io::parseConfig), with a print → re-read round trip: a configuration that parses must
// print (io::configToYaml) to text that parses back to a configuration printing the same text.
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_support.h"
#include "sgtllc/io/config_yaml.h"

using namespace sgtllc;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  Config config;
  if (!fuzz::readsOrRejects([&] { config = io::parseConfig(std::string(fuzz::bytesOf(data, size)), "fuzz"); })) {
    return 0;
  }
  const std::string printed = io::configToYaml(config);
  // No readsOrRejects: parseConfig validates, so rejecting its own print of a valid configuration is a finding.
  const Config again = io::parseConfig(printed, "printed");
  fuzz::require(io::configToYaml(again) == printed, "print → re-read → print is the identity");
  return 0;
}
