// `sgtllc localize --map MAP SEQ_DIR` / `--nodes NODE_DIR`: where is each frame of a sequence in a saved map?
// Nothing is inserted into the map, and every map frame is eligible (map/relocalizer.h).
#include <charconv>
#include <iostream>
#include <memory>

#include "commands.h"
#include "common.h"
#include "localization.h"
#include "sgtllc/eval/sequence_eval.h"
#include "sgtllc/io/csv.h"
#include "sgtllc/io/quote.h"
#include "sgtllc/map/map_file.h"
#include "sgtllc/map/relocalizer.h"

namespace sgtllc::cli {
namespace {

struct LocalizeOptions {
  std::string map, sequence, nodes, out, config;
  std::string labeller, labels_dir;  ///< --labeller, --labels-dir (as `sgtllc run`)
  int threads = 0;
  bool json = false;
  bool quiet = false;  ///< --quiet: the summary only, no line per frame
  bool force = false;
  bool track = false;  ///< --track: the frames are one stream (map::RelocalizationTracker)
};

/// The shortest text that reads back to @p v (as the project's other CSV writers).
void appendShortestCsv(std::string& out, double v) {
  char text[32];
  const auto end = std::to_chars(text, text + sizeof text, v).ptr;
  out.append(text, end);
}

void appendPose(std::string& out, const Eigen::Matrix4d& T) {
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 4; ++c) {
      out += ',';
      appendShortestCsv(out, T(r, c));
    }
  }
}

/// query,map_frame,localized,score,score_c,lateral, 12 entries of T_mapframe_query, 12 of T_world_query (empty
/// without map poses or candidate), tracked (1: accepted below σ_4 because it agrees with the track, `--track`):
/// one row per query frame. `tracked` is the last column so that the earlier columns keep their places.
std::string hitsCsv(const std::vector<Hit>& hits) {
  std::string out = "query,map_frame,localized,score,score_c,lateral";
  for (const char* T : {"T_mapframe_query", "T_world_query"}) {
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 4; ++c) out += "," + std::string(T) + "_" + std::to_string(r) + std::to_string(c);
    }
  }
  out += ",tracked\n";
  for (const Hit& h : hits) {
    const bool found = !h.map_frame.empty();
    const Candidate* best = found ? &h.r.search.candidates[static_cast<size_t>(h.r.search.best)] : nullptr;
    io::appendCsvField(out, h.query);
    out += ',';
    io::appendCsvField(out, h.map_frame);
    out += std::string(",") + (h.r.localized ? "1" : "0") + ",";
    appendShortestCsv(out, h.r.score);
    out += ',';
    appendShortestCsv(out, best ? best->match.score_c : 0.0);
    out += std::string(",") + (h.r.search.lateral ? "1" : "0");
    if (found) {
      appendPose(out, h.r.T_mapframe_query);
    } else {
      out += std::string(12, ',');
    }
    if (h.r.T_world_query) {
      appendPose(out, *h.r.T_world_query);
    } else {
      out += std::string(12, ',');
    }
    out += std::string(",") + (h.r.tracked ? "1" : "0") + "\n";
  }
  return out;
}

/// One line per query; the frame names come from a folder's file names and from the map file, so they are escaped
/// (quote.h) before they reach the terminal.
std::string hitLine(const Hit& h) {
  const std::string query = io::escapeContent(h.query, io::kNameBytes);
  const std::string map_frame = io::escapeContent(h.map_frame, io::kNameBytes);
  if (h.map_frame.empty()) return query + ": no map frame verified";
  const Eigen::Vector3d t = h.r.T_mapframe_query.topRightCorner<3, 1>();
  std::string line = query + (h.r.localized ? " -> " : " ?> ") + map_frame + "  score " + fixed(h.r.score, 3) +
                     "  t = (" + fixed(t.x(), 2) + ", " + fixed(t.y(), 2) + ", " + fixed(t.z(), 2) + ") m";
  if (h.r.T_world_query) {
    const Eigen::Vector3d w = h.r.T_world_query->topRightCorner<3, 1>();
    line += "  map position (" + fixed(w.x(), 2) + ", " + fixed(w.y(), 2) + ", " + fixed(w.z(), 2) + ") m";
  }
  return line + (h.r.tracked         ? "  (below verification.sigma_4, agrees with the track)"
                 : h.r.localized     ? ""
                 : h.r.weak_rotation ? "  (inlier centres nearly on a line, rotation not fixed: not localized)"
                                     : "  (below verification.sigma_4: not localized)");
}

void localizeCommand(const LocalizeOptions& o) {
  const Config config = loadConfigOption(o.config, o.threads, o.labeller);
  if (!o.out.empty()) checkWritable(o.out, o.force);
  const pipeline::FrameSource source = frameSource(o.sequence, o.nodes, config, o.labels_dir);
  const std::string& query_name = o.nodes.empty() ? o.sequence : o.nodes;
  const map::Relocalizer relocalizer(map::readMapFile(o.map, config), config, o.map);
  const map::Map& m = relocalizer.map();
  std::vector<double> frame_ms;
  int localized = 0;
  Progress progress("frames", source.size());
  const auto on_hit = [&](size_t index, const Hit& h) {
    localized += h.r.localized;
    frame_ms.push_back(h.r.search.timing.total_ms());
    if (!o.json && !o.quiet) {
      progress.clear();
      std::cout << hitLine(h) << "\n";
    }
    progress.update(index + 1, std::to_string(localized) + " localized");
  };
  const std::vector<Hit> hits = pipeline::localizeSequence(source, relocalizer, query_name, o.map, config.threads,
                                                           trackingOption(o.track), on_hit);
  progress.finish();
  if (!o.out.empty()) writeOutput(o.out, hitsCsv(hits), o.force);

  const double share = hits.empty() ? 0.0 : static_cast<double>(localized) / static_cast<double>(hits.size());
  if (o.json) {
    Json list = Json::array();
    for (const Hit& h : hits) {
      Json j = {{"query", h.query}, {"map_frame", h.map_frame.empty() ? Json() : Json(h.map_frame)},
                {"localized", h.r.localized}, {"tracked", h.r.tracked},
                {"weak_rotation", h.r.weak_rotation}, {"score", h.r.score}};
      if (!h.map_frame.empty()) j["T_mapframe_query"] = matrixJson(h.r.T_mapframe_query);
      if (h.r.T_world_query) j["T_world_query"] = matrixJson(*h.r.T_world_query);
      list.push_back(std::move(j));
    }
    std::cout << jsonText({{"map", o.map},
                           {"map_frames", m.size()},
                           {"map_poses", m.hasPoses()},
                           {"sequence", query_name},
                           {"track", o.track},
                           {"frames", hits.size()},
                           {"localized", localized},
                           {"localized_share", share},
                           {"ms_per_frame_median", eval::percentile(frame_ms, 0.5)},
                           {"ms_per_frame_p99", eval::percentile(frame_ms, 0.99)},
                           {"hits", list}})
              << "\n";
  } else {
    std::cout << "frames " << hits.size() << ", localized " << localized << " (" << fixed(100.0 * share, 1)
              << " %) in a map of " << m.size() << " frames, ms per frame: median "
              << fixed(eval::percentile(frame_ms, 0.5), 2) << ", p99 " << fixed(eval::percentile(frame_ms, 0.99), 2)
              << " (load not included)\n";
    if (!o.out.empty()) std::cout << "wrote " << o.out << "\n";
  }
}

}  // namespace

void addLocalizeCommand(CLI::App& app) {
  auto o = std::make_shared<LocalizeOptions>();
  CLI::App* cmd = app.add_subcommand("localize", "Relocalize the frames of a sequence in a saved map (`run --save-map`)");
  cmd->add_option("--map", o->map, "map file written by `sgtllc run --save-map`")->required();
  cmd->add_option("SEQ_DIR", o->sequence, kSequenceFolderHelp);
  cmd->add_option("--nodes", o->nodes, "instead of SEQ_DIR: a folder of node files NAME.txt, frames in name order");
  cmd->add_option("--out", o->out,
                  "write one CSV row per frame: query,map_frame,localized,score,score_c,lateral, T_mapframe_query "
                  "(3x4), T_world_query (3x4, with map poses), tracked (1: accepted by --track below sigma_4)");
  cmd->add_option("--config", o->config, "YAML configuration (its map fields must equal the map's: `sgtllc map info`)");
  addLabellerOption(cmd, &o->labeller);
  cmd->add_option("--labels-dir", o->labels_dir,
                  "read DIR/NNNNNN.label (e.g. a segmentation network's predictions) instead of SEQ_DIR/labels");
  cmd->add_option("--threads", o->threads, "worker threads (default: the config's `threads`)")
      ->check(CLI::Range(1, kMaxThreads));
  cmd->add_flag("--json", o->json, "print the summary and every frame's answer as one JSON object");
  cmd->add_flag("--quiet", o->quiet, "print the summary only, no line per frame");
  cmd->add_flag("--force", o->force, "overwrite an existing --out file");
  addTrackOption(cmd, &o->track);
  cmd->callback([o] {
    if (o->sequence.empty() == o->nodes.empty()) {
      throw CLI::ValidationError("localize", "give either SEQ_DIR (scans: velodyne/*.bin, or .bin/.pcd/.ply files) or --nodes NODE_DIR");
    }
    localizeCommand(*o);
  });
}

}  // namespace sgtllc::cli
