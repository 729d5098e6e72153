// `sgtllc run SEQ --odometry O --map A.sgtmap`: a new session against a saved map (docs/sessions.md).
#include <filesystem>
#include <iostream>

#include "accumulation.h"
#include "run_session.h"
#include "sgtllc/eval/false_loops.h"
#include "sgtllc/eval/sequence_eval.h"
#include "sgtllc/io/loops_csv.h"
#include "sgtllc/io/output_file.h"
#include "sgtllc/io/quote.h"
#include "sgtllc/map/map_file.h"
#include "sgtllc/pipeline/session_pipeline.h"

namespace sgtllc::cli {
namespace {

/// The default name of a session: its folder's name ("u7s8" for /data/u7s8/), of a map: its file's stem.
std::string defaultName(const std::string& path, bool stem) {
  std::filesystem::path p(path);
  if (!stem && !p.has_filename()) p = p.parent_path();
  const std::string name = stem ? p.stem().string() : p.filename().string();
  return name.empty() ? "session" : name;
}

}  // namespace

StreamedSession streamSession(const RunOptions& o, const Config& config) {
  StreamedSession out;
  pipeline::SessionOptions options;
  options.name = o.session_name.empty() ? defaultName(o.nodes.empty() ? o.sequence : o.nodes, false) : o.session_name;
  options.map_session = defaultName(o.map, true);
  out.name = options.name;
  out.pipeline = std::make_unique<pipeline::SessionPipeline>(map::readMapFile(o.map, config), config, options, o.map);
  pipeline::SessionPipeline& session = *out.pipeline;
  out.source = std::make_unique<pipeline::FrameSource>(frameSource(o.sequence, o.nodes, config, o.labels_dir));
  pipeline::FrameSource& source = *out.source;
  out.odometry = readOdometry(o.odometry, sequenceCalib(o.calib, o.sequence), o.pose_frame, source.size());
  applyAccumulation(source, o.accumulate, &out.odometry, o.sequence, o.calib, o.pose_frame);

  Progress progress("frames", source.size());
  pipeline::streamFrames(source, config.threads, [&](size_t index, pipeline::LoadedFrame& loaded) {
    const pipeline::SessionFrame f = session.addFrame(std::move(loaded), out.odometry.poses[index], source.name(index));
    out.frame_ms.push_back(f.own.detection.timing.total_ms() + f.in_map.search.timing.total_ms());
    if (!o.json && !o.quiet) {
      for (const std::optional<pipeline::ClosingLoop>* l : {&f.own.loop, &f.inter}) {
        if (!l->has_value()) continue;
        progress.clear();
        std::cout << ((*l)->edge.from < session.mapFrames() ? "inter-session loop " : "loop ")
                  << io::escapeContent((*l)->query, io::kNameBytes) << " -> "
                  << io::escapeContent((*l)->match, io::kNameBytes) << "  score " << fixed((*l)->score, 3) << "\n";
      }
    }
    progress.update(index + 1, std::to_string(session.loops().size()) + " loops");
  });
  progress.finish();
  return out;
}

void runSession(const RunOptions& o) {
  const Config config = loadConfigOption(o.config, o.threads, o.labeller);
  if (!o.out.empty()) checkWritable(o.out, o.force);
  if (!o.outputs.trajectory.empty()) checkWritable(o.outputs.trajectory, o.force);
  if (!o.save_map.empty()) checkWritable(o.save_map, o.force);
  StreamedSession run = streamSession(o, config);
  pipeline::SessionPipeline& session = *run.pipeline;
  const Odometry& odometry = run.odometry;
  const std::vector<double>& frame_ms = run.frame_ms;
  if (o.false_fraction > 0.0) {
    const map::Map& prior = session.map();
    std::vector<Eigen::Isometry3d> map_poses;
    for (const Eigen::Matrix4d& T : prior.poses) map_poses.emplace_back(T);
    for (pipeline::ClosingLoop& l :
         eval::falseInterSessionLoops(map_poses, session.loops(), o.false_fraction, o.seed, prior.names)) {
      session.addLoop(std::move(l));
    }
  }
  const pipeline::SessionClosing& closing = session.finish();
  const backend::SessionMerge& merge = closing.merge;
  int injected = 0, injected_rejected = 0;
  for (size_t k = 0; k < session.loops().size(); ++k) {
    if (!session.loops()[k].injected) continue;
    ++injected;
    injected_rejected += merge.result.loops[k].decision != backend::LoopDecision::kAccepted;
  }

  if (!o.out.empty()) {
    std::vector<io::LoopRecord> records;
    for (const pipeline::ClosingLoop& l : session.loops()) {
      if (!l.injected) records.push_back(pipeline::loopRecord(l));  // the loops found, not the test's
    }
    writeOutput(o.out, io::loopsCsvText(records, true), o.force);
  }
  const bool wants_placement = !o.outputs.trajectory.empty() || !o.save_map.empty();
  if (!merge.placed && wants_placement) {
    throw Error((o.sequence.empty() ? o.nodes : o.sequence) + ": not placed in " + o.map + ": of its " +
                std::to_string(merge.inter_loops - injected) + " inter-session loops fewer than " +
                std::to_string(config.backend.sessions.min_inter_loops) +
                " agree (backend.sessions.min_inter_loops); --out-trajectory and --save-map were not written");
  }
  if (!o.outputs.trajectory.empty()) {
    io::writeTrajectory(o.outputs.trajectory, io::withPoses(odometry.trajectory, merge.result.poses),
                        io::overwriteIf(o.force));
  }
  if (!o.save_map.empty()) map::writeMapFile(o.save_map, session.mergedMap(), io::overwriteIf(o.force));

  int added = 0;
  for (bool k : session.framesKept()) added += k;
  int intra = 0, intra_accepted = 0;
  for (size_t k = 0; k < session.loops().size(); ++k) {
    if (session.loops()[k].edge.from < session.mapFrames()) continue;
    ++intra;
    intra_accepted += merge.result.loops[k].decision == backend::LoopDecision::kAccepted;
  }
  const int frames = session.session().numFrames();
  if (o.json) {
    Json out = {{"sequence", o.nodes.empty() ? o.sequence : o.nodes},
                {"map", o.map},
                {"session", run.name},
                {"frames", frames},
                {"map_frames", session.mapFrames()},
                {"placed", merge.placed},
                {"inter_session_loops", merge.inter_loops - injected},
                {"inter_session_accepted", merge.inter_accepted},
                {"intra_session_loops", intra},
                {"intra_session_accepted", intra_accepted},
                {"ms_per_frame_median", eval::percentile(frame_ms, 0.5)},
                {"ms_per_frame_p99", eval::percentile(frame_ms, 0.99)},
                {"merge_ms", closing.ms}};
    out["frames_added_to_map"] = merge.placed ? added : 0;
    if (injected > 0) {
      out["injected_false_loops"] = injected;
      out["injected_rejected"] = injected_rejected;
    }
    if (!o.save_map.empty()) out["merged_map"] = o.save_map;
    Json list = Json::array();
    for (size_t k = 0; k < session.loops().size(); ++k) {
      const pipeline::ClosingLoop& l = session.loops()[k];
      list.push_back({{"query", l.query},
                      {"match", l.match},
                      {"inter_session", l.edge.from < session.mapFrames()},
                      {"injected", l.injected},
                      {"score", l.score},
                      {"decision", backend::loopDecisionName(merge.result.loops[k].decision)},
                      {"chi2", merge.result.loops[k].chi2}});
    }
    out["loop_list"] = list;
    std::cout << jsonText(out) << "\n";
    return;
  }
  std::cout << "frames " << frames << " against a map of " << session.mapFrames() << "; inter-session loops "
            << merge.inter_loops - injected << ", accepted " << merge.inter_accepted << "; intra-session loops " << intra
            << ", accepted " << intra_accepted << "; ms per frame (both searches): median "
            << fixed(eval::percentile(frame_ms, 0.5), 2) << ", p99 " << fixed(eval::percentile(frame_ms, 0.99), 2)
            << "; merge " << fixed(closing.ms, 1) << " ms\n";
  if (injected > 0) {
    std::cout << "injected false inter-session loops: " << injected << ", rejected " << injected_rejected
              << ", accepted " << injected - injected_rejected << "\n";
  }
  const std::string name = io::escapeContent(run.name, io::kNameBytes);
  std::cout << (merge.placed ? "session '" + name + "' placed in the map's frame\n"
                             : "session '" + name + "' NOT placed: fewer than " +
                                   std::to_string(config.backend.sessions.min_inter_loops) +
                                   " consistent inter-session loops; its poses stay in the odometry's frame\n");
  for (const std::string* path : {&o.out, &o.outputs.trajectory}) {
    if (!path->empty()) std::cout << "wrote " << *path << "\n";
  }
  if (!o.save_map.empty()) {
    std::cout << "wrote map " << o.save_map << " (" << session.mapFrames() + added << " frames: the map's "
              << session.mapFrames() << " and " << added << " of the session's " << frames
              << "; the others are places the map already has: docs/sessions.md, \"A map that does not grow with "
                 "revisits\")\n";
  }
}

}  // namespace sgtllc::cli
