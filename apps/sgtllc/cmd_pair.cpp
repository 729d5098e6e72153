// `sgtllc pair QUERY MATCH`: is QUERY a revisit of MATCH, and with which pose?
#include <algorithm>
#include <filesystem>
#include <iostream>
#include <memory>
#include <utility>
#include <vector>

#include "commands.h"
#include "common.h"
#include "pair_compare.h"
#include "sgtllc/io/nodes.h"
#include "sgtllc/io/output_file.h"
#include "sgtllc/io/pcd.h"
#include "sgtllc/io/ply.h"

namespace sgtllc::cli {
namespace {

struct PairOptions {
  std::string query, match;
  std::string labels_query, labels_match, label_field = "label";
  std::string config;
  std::string labeller;  ///< --labeller file|geometric
  std::string export_dir;
  std::string list;  ///< --list: pairs from a file instead of QUERY MATCH
  int threads = 0;   ///< --threads: pairs at once with --list, else the node extraction's (0: the config's)
  bool json = false;
  bool force = false;
};

std::vector<io::PlyEdge> graphEdges(const std::vector<Node>& nodes, const Config& config, int offset) {
  std::vector<io::PlyEdge> edges;
  const SemanticGraph g = buildGraph(nodes, config.graph, config.numClasses());
  for (const auto& [p, q] : g.edges()) edges.push_back(io::PlyEdge{p + offset, q + offset, {160, 160, 160}});
  return edges;
}

/// query.ply and match.ply (each graph in its own frame), matches.ply (the match graph with the query nodes moved
/// by T_match_query and one edge per association: green inlier, red outlier), both node sets as node files
/// (query_nodes.txt, match_nodes.txt) that `sgtllc pair` reads back, and as ASCII PCD (query_nodes.pcd,
/// match_nodes.pcd: x y z and the class index as label, pcl::PointXYZL) for PCL and point-cloud viewers.
struct ExportPaths {
  std::string q, m, qm, qn, mn, qp, mp;
};

/// Checks, before any work and without creating anything, that every export file can be written.
ExportPaths checkExport(const std::string& dir, bool force) {
  namespace fs = std::filesystem;
  if (fs::exists(dir) && !fs::is_directory(dir)) throw Error("cannot export to " + dir + ": it is a file, not a folder");
  const auto in_dir = [&](const char* name) { return (fs::path(dir) / name).string(); };
  ExportPaths p{in_dir("query.ply"), in_dir("match.ply"), in_dir("matches.ply"), in_dir("query_nodes.txt"),
                in_dir("match_nodes.txt"), in_dir("query_nodes.pcd"), in_dir("match_nodes.pcd")};
  io::checkOutputFiles({p.q, p.m, p.qm, p.qn, p.mn, p.qp, p.mp}, io::overwriteIf(force), true);
  return p;
}

/// Creates the folder (only now that the inputs have been read) and writes the files; each final rename refuses
/// a file that appeared since checkExport() unless --force.
void exportGraphs(const std::string& dir, const ExportPaths& p, const PairResult& r, const Config& config,
                  bool force) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec || !std::filesystem::is_directory(dir)) throw Error("cannot create export folder " + dir + ": " + ec.message());
  const io::Overwrite overwrite = io::overwriteIf(force);
  const auto& [q, m, qm, qn, mn, qp, mp] = p;
  const int num_classes = config.numClasses();
  io::writeGraphPly(q, r.query_nodes, graphEdges(r.query_nodes, config, 0), num_classes, overwrite);
  io::writeGraphPly(m, r.match_nodes, graphEdges(r.match_nodes, config, 0), num_classes, overwrite);
  io::writeNodesTxt(qn, r.query_nodes, config.labels, overwrite);
  io::writeNodesTxt(mn, r.match_nodes, config.labels, overwrite);
  io::writeNodesPcd(qp, r.query_nodes, num_classes, overwrite);
  io::writeNodesPcd(mp, r.match_nodes, num_classes, overwrite);

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
  io::writeGraphPly(qm, both, edges, num_classes, overwrite);
}

std::string inputSummary(const FrameNodes& f) {
  const std::string nodes = std::to_string(f.nodes.size()) + " nodes";
  return f.from_node_file ? "node file, " + nodes : std::to_string(f.points) + " points, " + nodes;
}

void printText(const PairOptions& o, const PairResult& r, const FrameNodes& q, const FrameNodes& mt,
               const Config& config, double load_ms) {
  const MatchResult& m = r.match;
  std::cout << "query  " << o.query << "  (" << inputSummary(q) << ")\n"
            << "match  " << o.match << "  (" << inputSummary(mt) << ")\n";
  std::cout << "loop: " << (r.is_loop ? "YES" : "no") << "   score " << fixed(m.score, 3)
            << (r.is_loop ? " > " : " <= ") << "sigma_4 " << config.verification.sigma_4 << "   score_c "
            << fixed(m.score_c, 3) << "\n";
  const size_t guided = numGuided(m);
  std::cout << "associations " << m.associations.size() - guided << ", inliers " << m.inliers.size();
  if (guided > 0) std::cout << " (" << guided << " paired by the pose: guided matching)";
  if (m.by_consistency) std::cout << "   (pairs chosen by geometric consistency, not the descriptors: algorithm §7.8)";
  if (m.rejection != Rejection::kNone) std::cout << "   (rejected: " << rejectionName(m.rejection) << ")";
  std::cout << "\n";
  const double offset = m.T_match_query.topRightCorner<3, 1>().norm();
  const double weight = offsetWeight(offset, config.verification);
  if (m.rejection == Rejection::kNone && weight < 1.0) {
    // Else a pose 25 m away with 16 inliers would print score 0 with no reason (algorithm §7, offset decay).
    std::cout << "score scaled by " << fixed(weight, 3) << " for the estimated offset " << fixed(offset, 2)
              << " m (verification.offset_decay_start / end " << config.verification.offset_decay_start << " / "
              << config.verification.offset_decay_end << " m)\n";
  }
  if (m.footprint.compared > 0) {
    std::cout << "footprint: " << fixed(m.footprint.share, 3) << " of " << m.footprint.compared
              << " structure cells agree under the pose (verification.min_footprint_overlap "
              << config.verification.min_footprint_overlap << ")\n";
    if (m.footprint.seen.judged > 0) {
      std::cout << "seen through: " << fixed(m.footprint.seen.share(), 3) << " of " << m.footprint.seen.judged
                << " structure returns by the other scan's beams under the pose (verification.max_seen_through "
                << config.verification.max_seen_through << ")\n";
    }
  }
  const FootprintShift& search = m.footprint_search;
  const bool shifted = search.compared > 0 && search.shift.squaredNorm() > 0.0;
  if (shifted) {
    std::cout << "footprint search: the nodes' pose moved by (" << fixed(search.shift.x(), 2) << ", "
              << fixed(search.shift.y(), 2) << ") m, where " << fixed(search.share, 3) << " of " << search.compared
              << " cells agree instead of " << fixed(search.unshifted_share, 3) << " (verification.footprint_search "
              << config.verification.footprint_search << " m, algorithm §7.9)\n";
  }
  if (m.rejection == Rejection::kNone) {
    std::cout << "T_match_query (maps query points into the match frame"
              << (r.refinement && r.refinement->used() ? ", refined by ICP" : "") << "):\n"
              << matrixText(m.T_match_query, "  ");
  }
  if (const auto& f = r.refinement) {
    std::cout << "refinement: " << refinementStatusName(f->status) << (f->used() ? "" : " (kept the SVD pose)")
              << "   fitness " << fixed(f->fitness, 3) << ", rmse " << fixed(f->rmse_m, 4) << " m, iterations "
              << f->iterations << ", points " << f->query_points << " / " << f->match_points << "\n";
    if (f->used()) {
      std::cout << "T_match_query before refinement (SVD" << (shifted ? ", moved by the footprint search" : "")
                << "):\n"
                << matrixText(f->T_match_query_seed, "  ");
    }
  }
  const StageTimes& t = r.timing;
  std::cout << "time (ms): load " << fixed(load_ms, 2) << ", extraction " << fixed(t.extraction_ms, 2)
            << ", description " << fixed(t.description_ms, 2) << ", verification " << fixed(t.verification_ms, 2)
            << ", refinement " << fixed(t.refinement_ms, 2) << "\n";
}

void runPair(const PairOptions& o) {
  if (!o.list.empty()) {
    if (!o.query.empty() || !o.match.empty() || !o.labels_query.empty() || !o.labels_match.empty() ||
        !o.export_dir.empty()) {
      throw CLI::ValidationError("pair --list", "takes the pairs from the list: no QUERY, MATCH, --labels-query, "
                                 "--labels-match or --export with it");
    }
    runPairList(o.list, o.label_field, loadConfigOption(o.config, 0, o.labeller), o.json, o.threads);
    return;
  }
  if (o.query.empty() || o.match.empty()) {
    throw CLI::ValidationError("pair", "give QUERY and MATCH, or --list FILE");
  }
  const Config config = loadConfigOption(o.config, o.threads, o.labeller);
  const ExportPaths paths = o.export_dir.empty() ? ExportPaths{} : checkExport(o.export_dir, o.force);
  ComparedPair c = compareFiles({o.query, o.match, o.labels_query, o.labels_match, o.label_field}, config);
  if (o.json) {
    std::cout << jsonText(pairJson(o.query, o.match, c.result, config, c.load_ms)) << "\n";
  } else {
    printText(o, c.result, c.query, c.match, config, c.load_ms);
  }
  if (!o.export_dir.empty()) exportGraphs(o.export_dir, paths, c.result, config, o.force);
}

}  // namespace

void addPairCommand(CLI::App& app) {
  auto o = std::make_shared<PairOptions>();
  CLI::App* cmd = app.add_subcommand("pair", "Compare two scans: loop or not, scores and the 6-DoF pose");
  cmd->add_option("QUERY", o->query, "query scan (.bin with labels, .pcd or .ply with a label field) or node file (.txt)");
  cmd->add_option("MATCH", o->match, "candidate scan it may revisit");
  cmd->add_option("--list", o->list,
                  "compare every pair of this file instead, in one process: one pair a line, QUERY,MATCH (CSV; "
                  "paths from the list's folder); prints a CSV row per pair, or with --json one JSON object a line");
  cmd->add_option("--threads", o->threads,
                  "with --list, pairs compared at once, each on one thread (the output does not depend on it); "
                  "alone, the node extraction's threads (config `threads`)")
      ->check(CLI::Range(1, kMaxThreads));
  cmd->add_option("--labels-query", o->labels_query,
                  "labels of QUERY, a uint32 or one byte a point (labels.format) (default: ../labels/NAME.label "
                  "beside velodyne/NAME.bin, else NAME.label)");
  cmd->add_option("--labels-match", o->labels_match, "labels of MATCH (same default)");
  cmd->add_option("--label-field", o->label_field, "PCD field (PLY vertex property) holding the per-point label")->capture_default_str();
  cmd->add_option("--config", o->config, "YAML configuration (see `sgtllc config`)");
  addLabellerOption(cmd, &o->labeller);
  cmd->add_flag("--json", o->json, "print one JSON object");
  cmd->add_option("--export", o->export_dir,
                  "write the graphs (query.ply, match.ply, matches.ply) and the nodes (*_nodes.txt) to this folder");
  cmd->add_flag("--force", o->force, "overwrite existing export files");
  cmd->callback([o] { runPair(*o); });
}

}  // namespace sgtllc::cli
