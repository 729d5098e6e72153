// `sgtllc run SEQ_DIR` / `sgtllc run --nodes NODE_DIR`: streams a sequence through the online detector.
#include <iostream>
#include <memory>
#include <sstream>

#include "commands.h"
#include "common.h"
#include "sgtllc/eval/frame_source.h"
#include "sgtllc/eval/sequence_eval.h"
#include "sgtllc/io/output_file.h"

namespace sgtllc::cli {
namespace {

struct RunOptions {
  std::string sequence;
  std::string nodes;
  std::string out;
  std::string config;
  int threads = 0;
  bool json = false;
  bool force = false;
};

struct Loop {
  std::string query, match;
  double score_t = 0.0, score_c = 0.0;
  Eigen::Matrix4d T = Eigen::Matrix4d::Identity();
};

std::string csv(const std::vector<Loop>& loops) {
  std::ostringstream s;
  s << "query,match,score,score_c,r11,r12,r13,tx,r21,r22,r23,ty,r31,r32,r33,tz\n";
  for (const Loop& l : loops) {
    s << l.query << "," << l.match << "," << fixed(l.score_t, 6) << "," << fixed(l.score_c, 6);
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 4; ++c) s << "," << fixed(l.T(r, c), 6);
    }
    s << "\n";
  }
  return s.str();
}

void runSequence(const RunOptions& o) {
  const Config config = loadConfigOption(o.config, o.threads);
  // Checked now, so a bad path fails before the run; the final rename checks again (io/output_file.h).
  if (!o.out.empty()) io::checkOutputFile(o.out, io::overwriteIf(o.force));
  const eval::FrameSource source = frameSource(o.sequence, o.nodes, config);
  LoopDetector detector(config);

  std::vector<Loop> loops;
  std::vector<double> frame_ms, load_ms;
  Progress progress("frames", source.size());
  eval::streamSequence(source, detector, config.threads,
                       [&](size_t index, const eval::LoadedFrame& loaded, const FrameResult& r) {
    frame_ms.push_back(r.timing.total_ms());
    load_ms.push_back(loaded.load_ms);
    const ExtractionStats& stats = loaded.stats;
    if (stats.nonfinite_points > 0 || stats.far_points > 0 || stats.unknown_label_points > 0) {
      progress.clear();
      warnAboutInput(source.name(index), stats, r.num_nodes);
    }
    if (const Candidate* c = r.loop()) {
      loops.push_back(Loop{source.name(index), source.name(static_cast<size_t>(c->frame)), c->match.score_t,
                           c->match.score_c, c->match.T_match_query});
      if (!o.json) {
        progress.clear();
        const Loop& l = loops.back();
        std::cout << "loop " << l.query << " -> " << l.match << "  score " << fixed(l.score_t, 3) << "  score_c "
                  << fixed(l.score_c, 3) << "  t = (" << fixed(l.T(0, 3), 2) << ", " << fixed(l.T(1, 3), 2) << ", "
                  << fixed(l.T(2, 3), 2) << ") m\n"
                  << std::flush;
      }
    }
    progress.update(index + 1, std::to_string(loops.size()) + " loops");
  });
  progress.finish();
  if (!o.out.empty()) io::writeFileAtomically(o.out, csv(loops), io::overwriteIf(o.force));

  const int n = detector.numFrames();
  const double bytes_per_frame = n ? static_cast<double>(detector.database().totalBytes()) / n : 0.0;
  if (o.json) {
    Json list = Json::array();
    for (const Loop& l : loops) {
      list.push_back({{"query", l.query},
                      {"match", l.match},
                      {"score", l.score_t},
                      {"score_c", l.score_c},
                      {"T_match_query", matrixJson(l.T)}});
    }
    const Json out = {{"sequence", o.nodes.empty() ? o.sequence : o.nodes},
                                {"frames", n},
                                {"loops", loops.size()},
                                {"ms_per_frame_median", eval::percentile(frame_ms, 0.5)},
                                {"ms_per_frame_p99", eval::percentile(frame_ms, 0.99)},
                                {"load_ms_median", eval::percentile(load_ms, 0.5)},
                                {"db_bytes_per_frame", bytes_per_frame},
                                {"loop_list", list}};
    std::cout << jsonText(out) << "\n";
  } else {
    std::cout << "frames " << n << ", loops " << loops.size() << ", ms per frame: median "
              << fixed(eval::percentile(frame_ms, 0.5), 2) << ", p99 " << fixed(eval::percentile(frame_ms, 0.99), 2)
              << " (load not included: median " << fixed(eval::percentile(load_ms, 0.5), 2) << " ms), database "
              << fixed(bytes_per_frame, 0) << " bytes per frame\n";
    if (!o.out.empty()) std::cout << "wrote " << o.out << "\n";
  }
}

}  // namespace

void addRunCommand(CLI::App& app) {
  auto o = std::make_shared<RunOptions>();
  CLI::App* cmd = app.add_subcommand("run", "Stream a sequence (scans and labels, or node files) through the online detector");
  cmd->add_option("SEQ_DIR", o->sequence, "folder with velodyne/NNNNNN.bin and labels/NNNNNN.label");
  cmd->add_option("--nodes", o->nodes,
                  "instead of SEQ_DIR: a folder of node files NAME.txt (x y z label rows), frames in name order");
  cmd->add_option("--out", o->out, "write the detected loops as CSV (query,match,score,score_c, 3x4 pose)");
  cmd->add_option("--config", o->config, "YAML configuration (see `sgtllc config`)");
  cmd->add_option("--threads", o->threads, "worker threads (default: the config's `threads`)")
      ->check(CLI::Range(1, kMaxThreads));
  cmd->add_flag("--json", o->json, "print the summary and the loops as one JSON object");
  cmd->add_flag("--force", o->force, "overwrite an existing --out file");
  cmd->callback([o] {
    if (o->sequence.empty() == o->nodes.empty()) {
      throw CLI::ValidationError("run", "give either SEQ_DIR (velodyne/ and labels/) or --nodes NODE_DIR");
    }
    runSequence(*o);
  });
}

}  // namespace sgtllc::cli
