// Node files written from a sequence, for the suites that run node input (the CLI's --nodes, the evaluation):
// apart from test_support.h, whose other helpers the core's suites use without the pipeline.
#pragma once

#include <filesystem>
#include <string>

#include "sgtllc/io/nodes.h"
#include "sgtllc/pipeline/frame_source.h"

namespace sgtllc::test {

/// Writes every frame of @p source as a node file DIR/NAME.txt (what a user with their own object extraction gives).
inline void writeNodeFiles(const pipeline::FrameSource& source, const std::string& dir) {
  std::filesystem::create_directories(dir);
  for (size_t i = 0; i < source.size(); ++i) {
    io::writeNodesTxt(dir + "/" + source.name(i) + ".txt", source.load(i).nodes);
  }
}

}  // namespace sgtllc::test
