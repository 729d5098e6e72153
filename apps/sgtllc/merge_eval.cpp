// A merge scored against the session's ground truth (docs/sessions.md, "Evaluating a merge").
#include "merge_eval.h"

#include <filesystem>
#include <iostream>

#include "sgtllc/eval/ground_truth.h"
#include "sgtllc/eval/metrics.h"
#include "sgtllc/eval/sequence_eval.h"
#include "sgtllc/eval/trajectory_error.h"
#include "sgtllc/io/quote.h"

namespace sgtllc::cli {
namespace {

/// A loop's pose is correct within these of the truth (the bound session-ate.py and BENCHMARKS.md use).
constexpr double kCorrectMetres = 1.0;
constexpr double kCorrectDegrees = 5.0;

struct LoopCounts {
  int found = 0, correct = 0, accepted = 0, accepted_wrong = 0;
};

Json countsJson(const LoopCounts& c) {
  return {{"found", c.found}, {"correct", c.correct}, {"accepted", c.accepted}, {"accepted_wrong", c.accepted_wrong}};
}

std::string countsText(const LoopCounts& c) {
  return std::to_string(c.found) + " found, " + std::to_string(c.correct) + " correct, " + std::to_string(c.accepted) +
         " accepted, " + std::to_string(c.accepted_wrong) + " of them wrong";
}

Json ateJson(const eval::AteResult& a) {
  return {{"aligned_rmse", a.aligned.rmse},     {"aligned_median", a.aligned.median}, {"aligned_max", a.aligned.max},
          {"unaligned_rmse", a.unaligned.rmse}, {"unaligned_median", a.unaligned.median}};
}

}  // namespace

void evalMerge(const RunOptions& o, const Config& config) {
  const std::filesystem::path dir(o.sequence);
  const std::string poses_path = (dir / "poses.txt").string();
  if (o.sequence.empty() || !std::filesystem::exists(poses_path)) {
    throw Error((o.sequence.empty() ? std::string("SEQ_DIR/poses.txt") : poses_path) +
                ": missing (evaluating a merge needs the session's ground-truth poses in the map's world)");
  }
  const eval::GroundTruth truth = eval::GroundTruth::fromKitti(poses_path, (dir / "calib.txt").string());
  StreamedSession run = streamSession(o, config);
  pipeline::SessionPipeline& session = *run.pipeline;
  const pipeline::FrameSource& source = *run.source;
  std::vector<Eigen::Isometry3d> session_truth;
  for (size_t i = 0; i < source.size(); ++i) {
    const long number = source.number(i);
    if (!truth.has(number)) throw Error(poses_path + ": no pose for frame " + source.name(i));
    session_truth.emplace_back(truth.pose(number));
  }
  const pipeline::SessionClosing& closing = session.finish();
  const backend::SessionMerge& merge = closing.merge;
  const map::Map& prior = session.map();
  const int m = session.mapFrames();

  LoopCounts inter, intra;
  for (size_t k = 0; k < session.loops().size(); ++k) {
    const backend::Edge& e = session.loops()[k].edge;
    const bool is_inter = e.from < m;
    const Eigen::Matrix4d from = is_inter ? prior.poses.at(static_cast<size_t>(e.from))
                                          : session_truth.at(static_cast<size_t>(e.from - m)).matrix();
    const Eigen::Matrix4d reference = from.inverse() * session_truth.at(static_cast<size_t>(e.to - m)).matrix();
    const bool correct =
        eval::poseError(e.T_from_to.matrix(), reference).succeeds(kCorrectMetres, kCorrectDegrees);
    const bool accepted = merge.result.loops.at(k).decision == backend::LoopDecision::kAccepted;
    LoopCounts& c = is_inter ? inter : intra;
    ++c.found;
    c.correct += correct;
    c.accepted += accepted;
    c.accepted_wrong += accepted && !correct;
  }
  const eval::AteResult merged = eval::absoluteTrajectoryError(session_truth, merge.result.poses);
  const eval::AteResult odometry = eval::absoluteTrajectoryError(session_truth, run.odometry.poses);
  int added = 0;
  for (bool k : session.framesKept()) added += k;
  if (!merge.placed) added = 0;
  const int frames = session.session().numFrames();

  if (o.json) {
    Json out = {{"sequence", o.sequence},
                {"map", o.map},
                {"session", run.name},
                {"frames", frames},
                {"placed", merge.placed},
                {"inter_session_loops", countsJson(inter)},
                {"intra_session_loops", countsJson(intra)},
                {"ate_merged_m", ateJson(merged)},
                {"ate_odometry_m", ateJson(odometry)},
                {"map_frames_before", m},
                {"map_frames_after", m + added},
                {"map_frames_unthinned", m + frames},
                {"ms_per_frame_median", eval::percentile(run.frame_ms, 0.5)},
                {"merge_ms", closing.ms}};
    std::cout << jsonText(out) << "\n";
    return;
  }
  std::cout << "session '" << io::escapeContent(run.name, io::kNameBytes) << "': " << frames << " frames against a map of "
            << m << "; " << (merge.placed ? "placed in the map's frame" : "NOT placed") << "\n"
            << "inter-session loops: " << countsText(inter) << " (a pose more than 1 m / 5 deg off, judged against the "
            << "map's stored poses)\n"
            << "intra-session loops: " << countsText(intra) << "\n"
            << "ATE of the merged trajectory against poses.txt: aligned RMSE " << fixed(merged.aligned.rmse, 3)
            << " m (median " << fixed(merged.aligned.median, 3) << "), "
            << (merge.placed ? "in the map's frame RMSE " + fixed(merged.unaligned.rmse, 3) + " m"
                             : std::string("not in the map's frame"))
            << "; the odometry aligned " << fixed(odometry.aligned.rmse, 3) << " m\n"
            << "map frames: " << m << " before, " << m + added << " after the merge (" << m + frames
            << " if every frame were kept)\n"
            << "ms per frame (both searches): median " << fixed(eval::percentile(run.frame_ms, 0.5), 2) << "; merge "
            << fixed(closing.ms, 1) << " ms\n";
}

}  // namespace sgtllc::cli
