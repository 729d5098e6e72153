// The simulator's manifest `simulation.txt` (sim::parseManifest), which `simulate --world-of` reads.
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_support.h"
#include "sgtllc/sim/manifest.h"

using namespace sgtllc;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(fuzz::bytesOf(data, size));
  fuzz::readsOrRejects([&] {
    const sim::SimConfig c = sim::parseManifest(text, "simulation.txt");
    // What it wrote it reads back the same: print → re-read → print is the identity.
    const std::string printed = sim::manifestText(c);
    fuzz::require(sim::manifestText(sim::parseManifest(printed, "again.txt")) == printed, "manifest round trip");
  });
  return 0;
}
