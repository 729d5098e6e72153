#include "sgtllc/pipeline/loop_edge.h"

#include <utility>

namespace sgtllc::pipeline {

backend::Matrix6d nominalLoopInformation(const backend::LoopNoise& noise) {
  // Eight centres on the corners of a 20 m cube around the sensor, fitted exactly: the rotation and translation
  // information of a typical urban loop (20–40 objects within ±25 m, about ten of them inliers).
  std::vector<Eigen::Vector3d> centres;
  for (int k = 0; k < 8; ++k) centres.emplace_back(k & 1 ? 10.0 : -10.0, k & 2 ? 10.0 : -10.0, k & 4 ? 10.0 : -10.0);
  return backend::loopInformation(centres, centres, Eigen::Isometry3d::Identity(), noise);
}

ClosingLoop detectedLoop(int query, const Candidate& c, const FrameDatabase& db, std::string query_name,
                         std::string match_name, const backend::LoopNoise& noise) {
  ClosingLoop loop;
  loop.query = std::move(query_name);
  loop.match = std::move(match_name);
  loop.score = c.match.score;
  loop.score_c = c.match.score_c;
  loop.edge.from = c.frame;
  loop.edge.to = query;
  loop.edge.T_from_to = Eigen::Isometry3d(c.match.T_match_query);
  loop.edge.kind = backend::EdgeKind::kLoop;
  if (c.refinement && c.refinement->used()) {
    // The ICP pose (registration.online) and its point-to-plane information (docs/registration.md).
    loop.edge.information = c.refinement->information;
    return loop;
  }
  try {
    loop.edge = backend::loopEdge(c.frame, query, c.match, db.nodes(query), db.nodes(c.frame), noise);
  } catch (const Error&) {
    // Collinear inlier centres leave a rotation unobservable: fall back to the nominal information.
    loop.edge.information = nominalLoopInformation(noise);
    loop.has_information = false;
  }
  return loop;
}

io::LoopRecord loopRecord(const ClosingLoop& loop) {
  io::LoopRecord r;
  r.query = loop.query;
  r.match = loop.match;
  r.query_index = loop.edge.to;
  r.match_index = loop.edge.from;
  r.score = loop.score;
  r.score_c = loop.score_c;
  r.T_match_query = loop.edge.T_from_to.matrix();
  if (loop.has_information) r.information = loop.edge.information;
  return r;
}

std::vector<ClosingLoop> csvLoops(const std::vector<io::LoopRecord>& records, const backend::LoopNoise& noise) {
  const std::vector<backend::Edge> edges = io::loopEdges(records, nominalLoopInformation(noise));
  std::vector<ClosingLoop> loops;
  for (size_t k = 0; k < records.size(); ++k) {
    ClosingLoop l;
    l.edge = edges[k];
    l.query = records[k].query;
    l.match = records[k].match;
    l.has_information = records[k].information.has_value();
    l.score = records[k].score;
    l.score_c = records[k].score_c;
    loops.push_back(std::move(l));
  }
  return loops;
}

}  // namespace sgtllc::pipeline
