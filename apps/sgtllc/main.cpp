// sgtllc: LiDAR loop closing with semantic graphs (SGT-LLC) from the command line.
#include <exception>
#include <iostream>

#include <CLI/CLI.hpp>

#include "build_info.h"
#include "commands.h"
#include "common.h"
#include "sgtllc/io/quote.h"
#include "sgtllc/memory_reuse.h"

int main(int argc, char** argv) {
  // Frame after frame, the buffers one frame frees serve the next instead of being faulted in afresh
  // (memory_reuse.h; BENCHMARKS.md, "Memory kept for the next frame").
  sgtllc::reuseFreedMemory();
  // And a page fault per 2 MB rather than per 4 KB where the kernel offers huge pages (BENCHMARKS.md, "Huge pages
  // for the heap").
  sgtllc::hugePageHeap();
  CLI::App app{"sgtllc: LiDAR loop closing with semantic graphs (SGT-LLC)"};
  app.require_subcommand(1);
  app.set_version_flag("--version", sgtllc::cli::softwareText());
  sgtllc::cli::addPairCommand(app);
  sgtllc::cli::addLabelCommand(app);
  sgtllc::cli::addRunCommand(app);
  sgtllc::cli::addOptimizeCommand(app);
  sgtllc::cli::addEvalCommand(app);
  sgtllc::cli::addSimulateCommand(app);
  sgtllc::cli::addLocalizeCommand(app);
  sgtllc::cli::addMapCommand(app);
  sgtllc::cli::addRepeatabilityCommand(app);
  sgtllc::cli::addConfigCommand(app);
  std::string& line = sgtllc::cli::commandLine();
  line = "sgtllc";
  for (int a = 1; a < argc; ++a) line += std::string(" ") + argv[a];
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // CLI11 prints the message (or the help); every command-line mistake exits with 2.
    return app.exit(e) == 0 ? 0 : sgtllc::cli::kExitUsage;
  } catch (const std::exception& e) {
    // Readers quote the content they repeat; a path built from a folder's file names may still hold control bytes.
    std::cerr << "sgtllc: error: " << sgtllc::io::escapeControls(e.what()) << "\n";
    return sgtllc::cli::kExitFailure;
  }
  return 0;
}
