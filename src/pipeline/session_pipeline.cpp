#include "sgtllc/pipeline/session_pipeline.h"

#include <chrono>
#include <cstdio>
#include <utility>

#include "elapsed.h"
#include "frame_reducer.h"
#include "sgtllc/backend/information.h"
#include "sgtllc/map/thinning.h"

namespace sgtllc::pipeline {
namespace {

const map::Map& withPoses(const map::Map& map, const std::string& source) {
  if (!map.hasPoses()) {
    throw Error(source + ": the map has no poses, so a session cannot be placed in its frame (save it with "
                         "`run --odometry`, or from a sequence with poses.txt and calib.txt)");
  }
  return map;
}

void checkOptions(const SessionOptions& o, const map::Map& map) {
  for (const std::string* name : {&o.name, &o.map_session}) {
    if (name->empty() || name->find('/') != std::string::npos) {
      throw Error("session name '" + *name + "' is empty or holds a '/'");
    }
  }
  const std::string& other = map.sessions.empty() ? o.map_session : std::string();
  bool taken = o.name == other;
  for (const map::MapSession& s : map.sessions) taken = taken || s.name == o.name;
  if (taken) throw Error("the map already has a session named '" + o.name + "': give the new session another name");
}

}  // namespace

SessionPipeline::SessionPipeline(map::Map map, const Config& config, SessionOptions options,
                                 const std::string& source)
    : options_((checkOptions(options, withPoses(map, source)), std::move(options))),
      relocalizer_(std::move(map), config, source),
      own_(config),
      reducer_(std::make_unique<FrameReducer>(config)) {}

SessionPipeline::~SessionPipeline() = default;

SessionFrame SessionPipeline::addFrame(LoadedFrame frame, const Eigen::Isometry3d& T_odometry_frame,
                                       std::string name) {
  if (closing_) throw Error("frame " + std::to_string(own_.numFrames()) + ": the session was finished");
  std::vector<Node> nodes = frame.nodes;
  Footprint footprint = frame.footprint;
  SessionFrame out;
  const int m = mapFrames();
  out.own = own_.addFrame(std::move(frame), T_odometry_frame, std::move(name));
  const std::string& query = own_.names().back();
  if (out.own.loop) {
    ClosingLoop l = *out.own.loop;
    l.edge.from += m;
    l.edge.to += m;
    l.query = options_.name + "/" + l.query;
    l.match = options_.name + "/" + l.match;
    loops_.push_back(std::move(l));
  }
  out.in_map = relocalizer_.localize(nodes, std::move(footprint));
  inter_loop_.push_back(-1);
  if (out.in_map.localized) {
    const Candidate& c = out.in_map.search.candidates.at(static_cast<size_t>(out.in_map.search.best));
    const map::Map& prior = relocalizer_.map();
    ClosingLoop l;
    l.query = options_.name + "/" + query;
    l.match = prior.names.at(static_cast<size_t>(c.frame));
    l.score = c.match.score;
    l.score_c = c.match.score_c;
    const backend::LoopNoise& noise = own_.config().backend.loops;
    try {
      l.edge = backend::loopEdge(c.frame, m + out.own.index, c.match, nodes, prior.database.nodes(c.frame), noise);
    } catch (const Error&) {
      // Collinear inlier centres: the nominal information, as a detected loop (loop_edge.h).
      l.edge.from = c.frame;
      l.edge.to = m + out.own.index;
      l.edge.T_from_to = Eigen::Isometry3d(c.match.T_match_query);
      l.edge.kind = backend::EdgeKind::kLoop;
      l.edge.information = nominalLoopInformation(noise);
      l.has_information = false;
    }
    out.inter = l;
    inter_loop_.back() = static_cast<int>(loops_.size());
    loops_.push_back(std::move(l));
  }
  return out;
}

SessionFrame SessionPipeline::addScan(const LabeledCloud& scan, const Eigen::Isometry3d& T_odometry_frame,
                                     std::string name) {
  return addFrame(reducer_->reduceScan(scan, own_.numFrames()), T_odometry_frame, std::move(name));
}

SessionFrame SessionPipeline::addNodes(std::vector<Node> nodes, const Eigen::Isometry3d& T_odometry_frame,
                                      std::string name) {
  LoadedFrame frame;
  frame.nodes = std::move(nodes);
  return addFrame(std::move(frame), T_odometry_frame, std::move(name));
}

void SessionPipeline::addLoop(ClosingLoop loop) {
  if (closing_) throw Error("a loop was added after finish()");
  const int m = mapFrames(), end = m + own_.numFrames();
  const backend::Edge& e = loop.edge;
  if (e.from < 0 || e.to < 0 || e.from >= end || e.to >= end || e.from == e.to) {
    throw Error("an added loop joins frames " + std::to_string(e.from) + " and " + std::to_string(e.to) +
                ": a loop joins two different frames of 0.." + std::to_string(m - 1) + " (the map's) and " +
                std::to_string(m) + ".." + std::to_string(end - 1) + " (the session's so far)");
  }
  if (e.from < m && e.to < m) throw Error("an added loop joins two map frames: the map's poses are fixed");
  if (e.to < m) {
    throw Error("an added loop ends in map frame " + std::to_string(e.to) +
                ": a loop goes from a map or session frame to a session frame");
  }
  loops_.push_back(std::move(loop));
}

const SessionClosing& SessionPipeline::finish() {
  if (closing_) throw Error("finish() was called already");
  if (own_.numFrames() == 0) throw Error("the session has no frames");
  backend::SessionGraph graph;
  for (const Eigen::Matrix4d& T : relocalizer_.map().poses) graph.map_poses.push_back(orthonormalised(Eigen::Isometry3d(T)));
  graph.odometry = own_.odometry();
  for (const ClosingLoop& l : loops_) graph.loops.push_back(l.edge);
  const auto start = std::chrono::steady_clock::now();
  auto closing = std::make_unique<SessionClosing>();
  closing->merge = backend::mergeSession(graph, own_.config().backend);
  closing->ms = msSince(start);
  // A frame the map recognised: its inter-session loop was accepted.
  const size_t n = static_cast<size_t>(own_.numFrames());
  std::vector<bool> recognised(n, false);
  for (size_t f = 0; f < n && f < inter_loop_.size(); ++f) {
    const int k = inter_loop_[f];
    recognised[f] = k >= 0 && closing->merge.result.loops.at(static_cast<size_t>(k)).decision ==
                                  backend::LoopDecision::kAccepted;
  }
  const backend::SessionSettings& s = own_.config().backend.sessions;
  const map::Map& map = relocalizer_.map();
  closing->kept = map::framesThatAdd(map.poses, map::frameSessions(map), closing->merge.result.poses, recognised,
                                     {s.keep_distance_m, s.keep_heading_deg, s.max_covering_sessions});
  closing_ = std::move(closing);
  return *closing_;
}

const std::vector<Eigen::Isometry3d>& SessionPipeline::poses() const {
  return closing_ ? closing_->merge.result.poses : own_.odometry();
}

std::vector<bool> SessionPipeline::framesKept() const {
  return closing_ ? closing_->kept : std::vector<bool>(static_cast<size_t>(own_.numFrames()), true);
}

map::Map SessionPipeline::mergedMap() const {
  if (!closing_) throw Error("the merged map needs finish() first");
  if (!closing_->merge.placed) {
    throw Error("session '" + options_.name + "' was not placed in the map (fewer than " +
                std::to_string(own_.config().backend.sessions.min_inter_loops) + " consistent inter-session loops were accepted)");
  }
  const map::Map& prior = relocalizer_.map();
  const FrameDatabase& own = own_.detector().database();
  map::Map merged;
  merged.config = prior.config;
  merged.names = prior.names;
  merged.poses = prior.poses;
  merged.sessions = prior.sessions;
  if (merged.sessions.empty()) merged.sessions.push_back({options_.map_session, 0, prior.size()});
  const std::vector<bool>& keep = closing_->kept;
  int kept = 0;
  for (bool k : keep) kept += k;
  merged.sessions.push_back({options_.name, prior.size(), kept});
  merged.database = prior.database.copy();
  for (int f = 0; f < own.size(); ++f) {
    if (!keep.at(static_cast<size_t>(f))) continue;
    merged.names.push_back(options_.name + "/" + own_.names().at(static_cast<size_t>(f)));
    merged.poses.push_back(closing_->merge.result.poses.at(static_cast<size_t>(f)).matrix());
    StoredFrame frame;
    frame.nodes = own.nodes(f);
    frame.global.assign(own.global(f), own.global(f) + own.globalDimension());
    merged.database.add(std::move(frame));
  }
  // Footprints for all frames or none: a map without them stays without; session frames without one get an empty one.
  if (!prior.footprints.empty()) {
    merged.footprints = prior.footprints;
    const std::vector<Footprint>& fp = own_.detector().footprints();
    for (int f = 0; f < own.size(); ++f) {
      if (keep.at(static_cast<size_t>(f))) merged.footprints.push_back(f < static_cast<int>(fp.size()) ? fp[f] : Footprint{});
    }
  }
  map::checkFrames(merged, "merged map");
  return merged;
}

}  // namespace sgtllc::pipeline
