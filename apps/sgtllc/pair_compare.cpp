// One pair of scan files compared, and its JSON object (pair_compare.h).
#include "pair_compare.h"

#include <algorithm>
#include <chrono>
#include <utility>
#include <vector>

namespace sgtllc::cli {

/// Pairs of MatchResult::associations that guided matching added (algorithm §7.2), not LA.
size_t numGuided(const MatchResult& m) {
  return static_cast<size_t>(std::count_if(m.associations.begin(), m.associations.end(),
                                           [](const NodeMatch& a) { return a.guided; }));
}

void warnInputs(const PairFiles& files, const ComparedPair& c) {
  for (const auto& [name, f] :
       {std::pair<const std::string&, const FrameNodes&>{files.query, c.query}, {files.match, c.match}}) {
    warnAboutInput(name, f.stats, static_cast<int>(f.nodes.size()), f.from_node_file ? "node rows" : "points");
  }
}

ComparedPair compareFiles(const PairFiles& files, const Config& config, bool warn) {
  ComparedPair c;
  c.query = loadFrameNodes(files.query, files.labels_query, files.label_field, config);
  c.match = loadFrameNodes(files.match, files.labels_match, files.label_field, config);
  FrameNodes& q = c.query;
  FrameNodes& mt = c.match;
  if (warn) warnInputs(files, c);
  const LabelMap labels(effectiveLabelConfig(config));
  // Node files carry no points: no footprint check, and the SVD pose stands.
  const bool scans = !q.from_node_file && !mt.from_node_file;
  PairResult& r = c.result;
  r = comparePair(q.nodes, mt.nodes, config, scans ? std::move(q.footprint) : Footprint{},
                  scans ? std::move(mt.footprint) : Footprint{});
  r.extraction_query = q.stats;
  r.extraction_match = mt.stats;
  r.timing.extraction_ms = q.extraction_ms + mt.extraction_ms;
  const auto refine_start = std::chrono::steady_clock::now();
  if (scans) {
    // Each scan is given up to its registration points, one after the other: the peak holds one big scan.
    std::vector<Eigen::Vector3f> query_points = queryPoints(std::move(q.cloud), labels, config.registration);
    refinePair(&r, query_points, matchPoints(std::move(mt.cloud), labels, config.registration), config);
  }
  if (r.refinement) {
    r.timing.refinement_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - refine_start).count();
  }
  c.load_ms = q.load_ms + mt.load_ms;
  return c;
}

namespace {

/// The footprint check (algorithm §7.7), or null where it did not run (node files, the check off, no pose).
Json footprintJson(const FootprintOverlap& f, const VerificationConfig& config) {
  if (f.compared == 0) return nullptr;
  return {{"share", f.share},
          {"compared_cells", f.compared},
          {"min_share", config.min_footprint_overlap},
          {"seen_through", f.seen.share()},
          {"sight_judged", f.seen.judged}};
}

Json footprintSearchJson(const FootprintShift& s) {
  if (s.compared == 0) return nullptr;
  return {{"shift_m", {s.shift.x(), s.shift.y()}},
          {"share", s.share},
          {"unshifted_share", s.unshifted_share},
          {"compared_cells", s.compared}};
}

}  // namespace

Json pairJson(const std::string& query, const std::string& match, const PairResult& r, const Config& config,
              double load_ms) {
  const MatchResult& m = r.match;
  const size_t guided = numGuided(m);
  Json matches = Json::array();
  std::vector<bool> inlier(m.associations.size(), false);
  for (int k : m.inliers) inlier[k] = true;
  for (size_t k = 0; k < m.associations.size(); ++k) {
    const NodeMatch& a = m.associations[k];
    matches.push_back({{"query_node", a.query},
                       {"match_node", a.match},
                       {"class", config.labels.className(r.query_nodes[a.query].label)},
                       {"similarity", a.similarity},
                       {"inlier", static_cast<bool>(inlier[k])},
                       {"guided", a.guided}});
  }
  Json refinement = nullptr;
  if (const auto& f = r.refinement) {
    Json information = Json::array();
    for (int i = 0; i < 6; ++i) {
      Json row = Json::array();
      for (int j = 0; j < 6; ++j) row.push_back(f->information(i, j));
      information.push_back(row);
    }
    refinement = {{"status", refinementStatusName(f->status)},
                  {"used", f->used()},
                  {"fitness", f->fitness},
                  {"rmse_m", f->rmse_m},
                  {"iterations", f->iterations},
                  {"query_points", f->query_points},
                  {"match_points", f->match_points},
                  {"T_match_query_svd", matrixJson(f->T_match_query_seed)},
                  {"information", information}};
  }
  return {{"query", query},
          {"match", match},
          {"loop", r.is_loop},
          {"score", m.score},
          {"score_t", m.score},
          {"score_c", m.score_c},
          {"rejection", rejectionName(m.rejection)},
          {"offset_weight", offsetWeight(m.T_match_query.topRightCorner<3, 1>().norm(),
                                         config.verification)},
          {"nodes_query", r.query_nodes.size()},
          {"nodes_match", r.match_nodes.size()},
          {"associations", m.associations.size() - guided},
          {"guided_pairs", guided},
          {"inliers", m.inliers.size()},
          {"path", m.by_consistency ? "consistency" : "descriptors"},
          {"footprint_search", footprintSearchJson(m.footprint_search)},
          {"footprint", footprintJson(m.footprint, config.verification)},
          {"matches", matches},
          {"T_match_query", matrixJson(m.T_match_query)},
          {"refinement", refinement},
          {"timing_ms", timingJson(r.timing, load_ms)}};
}

}  // namespace sgtllc::cli
