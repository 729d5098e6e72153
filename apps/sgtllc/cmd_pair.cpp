// `sgtllc pair QUERY MATCH`: is QUERY a revisit of MATCH, and with which pose?
#include <chrono>
#include <filesystem>
#include <iostream>
#include <memory>

#include "commands.h"
#include "common.h"
#include "sgtllc/io/ply.h"

namespace sgtllc::cli {
namespace {

struct PairOptions {
  std::string query, match;
  std::string labels_query, labels_match, label_field = "label";
  std::string config;
  std::string export_dir;
  bool json = false;
  bool force = false;
};

const char* rejectionText(Rejection r) {
  switch (r) {
    case Rejection::kNone:
      return "none";
    case Rejection::kFewAssociations:
      return "few_associations";
    case Rejection::kRansacFailed:
      return "ransac_failed";
  }
  return "?";
}

std::vector<io::PlyEdge> graphEdges(const std::vector<Node>& nodes, const Config& config, int offset) {
  std::vector<io::PlyEdge> edges;
  const SemanticGraph g = buildGraph(nodes, config.graph);
  for (const auto& [p, q] : g.edges()) edges.push_back(io::PlyEdge{p + offset, q + offset, {160, 160, 160}});
  return edges;
}

/// query.ply and match.ply (each graph in its own frame) and matches.ply: the match graph with the query nodes
/// moved by T_match_query and one edge per association (green inlier, red outlier).
void exportGraphs(const std::string& dir, const PairResult& r, const Config& config, bool force) {
  namespace fs = std::filesystem;
  fs::create_directories(dir);
  const std::string q = (fs::path(dir) / "query.ply").string();
  const std::string m = (fs::path(dir) / "match.ply").string();
  const std::string qm = (fs::path(dir) / "matches.ply").string();
  for (const auto& path : {q, m, qm}) checkWritable(path, force);
  io::writeGraphPly(q, r.query_nodes, graphEdges(r.query_nodes, config, 0));
  io::writeGraphPly(m, r.match_nodes, graphEdges(r.match_nodes, config, 0));

  std::vector<Node> both = r.match_nodes;
  const int offset = static_cast<int>(both.size());
  for (Node n : r.query_nodes) {
    n.centre = r.match.T_match_query.topLeftCorner<3, 3>() * n.centre + r.match.T_match_query.topRightCorner<3, 1>();
    both.push_back(n);
  }
  std::vector<io::PlyEdge> edges;
  std::vector<bool> inlier(r.match.associations.size(), false);
  for (int k : r.match.inliers) inlier[k] = true;
  for (size_t k = 0; k < r.match.associations.size(); ++k) {
    const NodeMatch& a = r.match.associations[k];
    edges.push_back(io::PlyEdge{a.match, offset + a.query,
                                inlier[k] ? std::array<uint8_t, 3>{0, 200, 0} : std::array<uint8_t, 3>{220, 0, 0}});
  }
  io::writeGraphPly(qm, both, edges);
}

void printText(const PairOptions& o, const PairResult& r, const LabeledCloud& qc, const LabeledCloud& mc,
               const Config& config, double load_ms) {
  const MatchResult& m = r.match;
  std::cout << "query  " << o.query << "  (" << qc.points.size() << " points, " << r.query_nodes.size()
            << " nodes)\n"
            << "match  " << o.match << "  (" << mc.points.size() << " points, " << r.match_nodes.size()
            << " nodes)\n";
  std::cout << "loop: " << (r.is_loop ? "YES" : "no") << "   score_t " << fixed(m.score_t, 3)
            << (r.is_loop ? " > " : " <= ") << "sigma_4 " << config.verification.sigma_4 << "   score_c "
            << fixed(m.score_c, 3) << "\n";
  std::cout << "associations " << m.associations.size() << ", inliers " << m.inliers.size();
  if (m.rejection != Rejection::kNone) std::cout << "   (rejected: " << rejectionText(m.rejection) << ")";
  std::cout << "\n";
  if (m.rejection == Rejection::kNone) {
    std::cout << "T_match_query (maps query points into the match frame):\n" << matrixText(m.T_match_query, "  ");
  }
  const StageTimes& t = r.timing;
  std::cout << "time (ms): load " << fixed(load_ms, 2) << ", extraction " << fixed(t.extraction_ms, 2)
            << ", description " << fixed(t.description_ms, 2) << ", verification " << fixed(t.verification_ms, 2)
            << "\n";
}

void printJson(const PairOptions& o, const PairResult& r, double load_ms) {
  const MatchResult& m = r.match;
  Json matches = Json::array();
  std::vector<bool> inlier(m.associations.size(), false);
  for (int k : m.inliers) inlier[k] = true;
  for (size_t k = 0; k < m.associations.size(); ++k) {
    const NodeMatch& a = m.associations[k];
    matches.push_back({{"query_node", a.query},
                       {"match_node", a.match},
                       {"class", kClassNames[r.query_nodes[a.query].label]},
                       {"similarity", a.similarity},
                       {"inlier", static_cast<bool>(inlier[k])}});
  }
  const Json out = {{"query", o.query},
                              {"match", o.match},
                              {"loop", r.is_loop},
                              {"score", m.score_t},
                              {"score_c", m.score_c},
                              {"rejection", rejectionText(m.rejection)},
                              {"nodes_query", r.query_nodes.size()},
                              {"nodes_match", r.match_nodes.size()},
                              {"associations", m.associations.size()},
                              {"inliers", m.inliers.size()},
                              {"matches", matches},
                              {"T_match_query", matrixJson(m.T_match_query)},
                              {"timing_ms", timingJson(r.timing, load_ms)}};
  std::cout << out.dump(2) << "\n";
}

void runPair(const PairOptions& o) {
  const Config config = loadConfigOption(o.config, 0);
  const auto start = std::chrono::steady_clock::now();
  const LabeledCloud qc = loadScan(o.query, o.labels_query, o.label_field);
  const LabeledCloud mc = loadScan(o.match, o.labels_match, o.label_field);
  const double load_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  const PairResult r = comparePair(qc, mc, config);
  warnAboutInput(o.query, r.extraction_query, static_cast<int>(r.query_nodes.size()));
  warnAboutInput(o.match, r.extraction_match, static_cast<int>(r.match_nodes.size()));
  if (o.json) {
    printJson(o, r, load_ms);
  } else {
    printText(o, r, qc, mc, config, load_ms);
  }
  if (!o.export_dir.empty()) exportGraphs(o.export_dir, r, config, o.force);
}

}  // namespace

void addPairCommand(CLI::App& app) {
  auto o = std::make_shared<PairOptions>();
  CLI::App* cmd = app.add_subcommand("pair", "Compare two scans: loop or not, scores and the 6-DoF pose");
  cmd->add_option("QUERY", o->query, "query scan (.bin with labels, or .pcd with a label field)")->required();
  cmd->add_option("MATCH", o->match, "candidate scan it may revisit")->required();
  cmd->add_option("--labels-query", o->labels_query,
                  "labels of QUERY (default: ../labels/NAME.label beside velodyne/NAME.bin, else NAME.label)");
  cmd->add_option("--labels-match", o->labels_match, "labels of MATCH (same default)");
  cmd->add_option("--label-field", o->label_field, "PCD field holding the per-point label")->capture_default_str();
  cmd->add_option("--config", o->config, "YAML configuration (see `sgtllc config`)");
  cmd->add_flag("--json", o->json, "print one JSON object");
  cmd->add_option("--export", o->export_dir, "write query.ply, match.ply and matches.ply (graphs) to this folder");
  cmd->add_flag("--force", o->force, "overwrite existing export files");
  cmd->callback([o] { runPair(*o); });
}

}  // namespace sgtllc::cli
