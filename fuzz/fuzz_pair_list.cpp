// Pair lists `query candidate label` for `sgtllc eval --pairs` (eval::readPairList).
#include <cstddef>
#include <cstdint>

#include "fuzz_support.h"
#include "sgtllc/eval/pair_eval.h"

using namespace sgtllc;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const fuzz::ScratchFile file("pairs.txt");
  file.write(fuzz::bytesOf(data, size));
  fuzz::readsOrRejects([&] {
    for (const eval::LoopPairLabel& p : eval::readPairList(file.path())) {
      fuzz::require(p.query >= 0 && p.candidate >= 0, "frame numbers are not negative");
    }
  });
  return 0;
}
