// The configuration key table: one Field per key of sgtllc::Config, with its comment, printer and parser (the
// kinds of value in config_field_kinds.h; here the label fields whose values are maps and lists of their own).
#include "config_fields.h"

#include <utility>

#include "config_field_kinds.h"
#include "config_yaml_backend.h"
#include "sgtllc/io/quote.h"

namespace sgtllc::io::detail {
namespace {

Field customMap() {
  return Field{
      "labels.custom_map",
      "raw id: class index 0..C-1 (building … traffic-sign, then extra classes) or -1 (known, dropped); "
      "used with preset custom",
      [](const Config& c) {
        std::string s = "{";
        for (const auto& [id, cls] : c.labels.custom_map) {
          s += (s.size() > 1 ? ", " : "") + std::to_string(id) + ": " + std::to_string(cls);
        }
        return s + "}";
      },
      [](Config& c, const YAML::Node& n) -> std::string {
        if (!n.IsMap() && !n.IsNull()) return "expected a map of id: class";
        c.labels.custom_map.clear();
        if (n.IsNull()) return "";
        const int last = c.labels.numClasses() - 1;  // labels.extra_classes is read first (parseConfig)
        for (const auto& kv : n) {
          long long id = 0, cls = 0;
          if (!parseInt(scalarText(kv.first), 0, 0xFFFF, &id)) return "ids must be integers 0..65535";
          if (!parseInt(scalarText(kv.second), -1, last, &cls)) {
            return "classes must be integers -1.." + std::to_string(last) + " (id " + std::to_string(id) + ")";
          }
          // Spellings such as 50 and 050 pass the duplicate-key scan but name the same id.
          if (c.labels.custom_map.count(static_cast<uint32_t>(id))) {
            return "id " + std::to_string(id) + " is listed twice";
          }
          c.labels.custom_map[static_cast<uint32_t>(id)] = static_cast<int>(cls);
        }
        return "";
      }};
}

/// One entry of labels.extra_classes, `{name: NAME, ids: [ID, …]}`; returns an error text ("" on success).
std::string readExtraClass(const YAML::Node& n, ExtraClass* out) {
  if (!n.IsMap()) return "expected a map {name: NAME, ids: [ID, ...]}";
  bool has_name = false;
  for (const auto& kv : n) {
    const std::string key = scalarText(kv.first);
    if (key == "name") {
      if (!kv.second.IsScalar()) return "name: expected a class name";
      out->name = kv.second.Scalar();
      has_name = true;
    } else if (key == "ids") {
      if (!kv.second.IsSequence()) return "ids: expected a list of raw ids, e.g. [10, 252]";
      const std::string err = readIds(kv.second, &out->ids);
      if (!err.empty()) return err;
    } else {
      return "unknown key " + quoteContent(key) + " (expected name and ids)";
    }
  }
  return has_name ? "" : "missing name";
}

Field extraClasses() {
  return Field{
      "labels.extra_classes",
      "classes 7, 8, … beyond the seven, each {name, ids} with its own cluster.NAME; at most 16 classes C in all "
      "(local descriptor C²×3, G1/G3 2·C², G2 C³)",
      [](const Config& c) {
        std::string s = "[";
        for (const ExtraClass& e : c.labels.extra_classes) {
          s += (s.size() > 1 ? ", " : "") + std::string("{name: ") + e.name + ", ids: " + idsText(e.ids) + "}";
        }
        return s + "]";
      },
      [](Config& c, const YAML::Node& n) -> std::string {
        if (!n.IsSequence() && !n.IsNull()) return "expected a list of {name: NAME, ids: [ID, ...]}";
        c.labels.extra_classes.clear();
        if (n.IsNull()) return "";
        for (size_t k = 0; k < n.size(); ++k) {
          ExtraClass extra;
          const std::string err = readExtraClass(n[k], &extra);
          if (!err.empty()) return "entry " + std::to_string(k) + ": " + err;
          c.labels.extra_classes.push_back(std::move(extra));
        }
        return "";
      }};
}

/// association.entries as the letters of the kept vertices, e.g. "ijk" or "ik".
Field entriesField() {
  return Field{"association.entries", "sub-vector entries compared, by vertex: any of i, j, k (ablation)",
               [](const Config& c) {
                 std::string s;
                 for (int v = 0; v < 3; ++v) {
                   if (c.association.entries & (1u << v)) s += "ijk"[v];
                 }
                 return s;
               },
               [](Config& c, const YAML::Node& n) -> std::string {
                 const std::string s = scalarText(n);
                 unsigned mask = 0;
                 for (char ch : s) {
                   const size_t v = std::string("ijk").find(ch);
                   if (v == std::string::npos || (mask & (1u << v))) return "expected distinct letters from i, j, k";
                   mask |= 1u << v;
                 }
                 if (mask == 0) return "expected distinct letters from i, j, k";
                 c.association.entries = mask;
                 return "";
               }};
}

}  // namespace

std::vector<Field> fieldsFor(const LabelConfig& labels) {
  std::vector<Field> f;
  f.push_back(choice<LabelPreset>("labels.preset", "id convention of the input labels (algorithm §1, §8)",
                                  [](Config& c) -> LabelPreset& { return c.labels.preset; },
                                  {{"semantickitti", LabelPreset::kSemanticKittiRaw},
                                   {"semantickitti_learning", LabelPreset::kSemanticKittiLearning},
                                   {"mulran", LabelPreset::kMulRan},
                                   {"mcd", LabelPreset::kMcd},
                                   {"nuscenes", LabelPreset::kNuScenes},
                                   {"custom", LabelPreset::kCustom}}));
  f.push_back(choice<LabelFormat>("labels.format",
                                  "label files: 4 bytes (uint32) or 1 byte (uint8) a point; auto tells them by size",
                                  [](Config& c) -> LabelFormat& { return c.labels.format; },
                                  {{"auto", LabelFormat::kAuto},
                                   {"uint32", LabelFormat::kUint32},
                                   {"uint8", LabelFormat::kUint8}}));
  f.push_back(customMap());
  f.push_back(extraClasses());
  f.push_back(choice<LabelSource>("labeller.source",
                                  "per-point classes from the label files, the scan's geometry, or both (hybrid) (docs/labeller.md)",
                                  [](Config& c) -> LabelSource& { return c.labeller.source; },
                                  {{"file", LabelSource::kFile}, {"geometric", LabelSource::kGeometric}, {"hybrid", LabelSource::kHybrid}}));
  const BackendFieldMakers makers{[&f](auto k, auto c, auto r) { f.push_back(number(k, c, r)); },
                                  [&f](auto k, auto c, auto r) { f.push_back(integer<int>(k, c, r)); },
                                  [&f](auto k, auto c, auto r, auto n) { f.push_back(choice(k, c, r, n)); },
                                  [&f](auto k, auto c, auto r) { f.push_back(boolean(k, c, r)); },
                                  [&f](auto k, auto c, auto r) { f.push_back(idList(k, c, r)); }};
  addLabellerFields(makers);
  for (int k = 0; k < labels.numClasses(); ++k) {
    const std::string p = "cluster." + labels.className(k) + ".";
    f.push_back(number(p + "voxel", "voxel leaf (m); 0 = no downsampling",
                       [k](Config& c) -> double& { return c.cluster.classes.at(k).voxel; }));
    f.push_back(number(p + "radius", "FEC radius r (m)",
                       [k](Config& c) -> double& { return c.cluster.classes.at(k).radius; }));
    f.push_back(integer<int>(p + "min_size", "minimum cluster size (voxels if voxel > 0, else points)",
                        [k](Config& c) -> int& { return c.cluster.classes.at(k).min_size; }));
  }
  f.push_back(integer<int>("cluster.max_neighbors", "FEC neighbour cap per radius query, seed included",
                      [](Config& c) -> int& { return c.cluster.max_neighbors; }));
  f.push_back(number("cluster.duplicate_radius", "skip a cluster this close to an accepted same-class centre (m)",
                     [](Config& c) -> double& { return c.cluster.duplicate_radius; }));
  f.push_back(choice<CentreSource>("cluster.centre", "node centre: mean of original points or of voxel centroids",
                                   [](Config& c) -> CentreSource& { return c.cluster.centre; },
                                   {{"points", CentreSource::kPoints}, {"voxels", CentreSource::kVoxels}}));
  f.push_back(number("graph.sigma_d", "σ_d: edge iff centre distance < σ_d (m)",
                     [](Config& c) -> double& { return c.graph.sigma_d; }));
  f.push_back(integer<int>("graph.max_nodes", "most nodes per frame (a scan keeps its largest clusters)",
                           [](Config& c) -> int& { return c.graph.max_nodes; }));
  f.push_back(boolean("graph.allow_k_equals_i", "allow the path i→j→i (authors' code)",
                      [](Config& c) -> bool& { return c.graph.allow_k_equals_i; }));
  f.push_back(choice<SubVectorKind>("descriptor.kind", "slot entries: dot products, angles only, lengths only",
                                    [](Config& c) -> SubVectorKind& { return c.descriptor.kind; },
                                    {{"dot", SubVectorKind::kDotProducts},
                                     {"angle", SubVectorKind::kAngles},
                                     {"length", SubVectorKind::kLengths}}));
  f.push_back(choice<SubVectorOrder>("descriptor.order", "sub-vector entries: (a_i,a_j,a_k) or (a_i,a_k,-a_j)",
                                     [](Config& c) -> SubVectorOrder& { return c.descriptor.order; },
                                     {{"paper", SubVectorOrder::kPaper}, {"code", SubVectorOrder::kCode}}));
  f.push_back(choice<GlobalMode>("descriptor.global_mode", "global descriptor (algorithm §5)",
                                 [](Config& c) -> GlobalMode& { return c.descriptor.global_mode; },
                                 {{"G1", GlobalMode::kG1}, {"G2", GlobalMode::kG2}, {"G3", GlobalMode::kG3}}));
  f.push_back(choice<RetrievalKey>("retrieval.key", "stored, searched key: class-pair distance histogram or Des^G",
                                   [](Config& c) -> RetrievalKey& { return c.retrieval.key; },
                                   {{"histogram", RetrievalKey::kDistanceHistogram},
                                    {"global", RetrievalKey::kGlobalDescriptor}}));
  f.push_back(integer<int>("retrieval.histogram_bins", "distance-histogram bins per class pair",
                           [](Config& c) -> int& { return c.retrieval.histogram_bins; }));
  f.push_back(number("retrieval.histogram_range", "distances the histogram covers (m)",
                     [](Config& c) -> double& { return c.retrieval.histogram_range; }));
  f.push_back(integer<int>("retrieval.num_candidates", "K: candidates retrieved per query",
                      [](Config& c) -> int& { return c.retrieval.num_candidates; }));
  f.push_back(integer<int>("retrieval.exclude_recent", "G: query q searches frames <= q - G",
                      [](Config& c) -> int& { return c.retrieval.exclude_recent; }));
  f.push_back(integer<int>("retrieval.warmup_frames", "no query before this many frames (authors' code: 150)",
                      [](Config& c) -> int& { return c.retrieval.warmup_frames; }));
  f.push_back(choice<RetrievalMethod>("retrieval.method", "nearest-neighbour search",
                                      [](Config& c) -> RetrievalMethod& { return c.retrieval.method; },
                                      {{"brute_force", RetrievalMethod::kBruteForce},
                                       {"kdtree", RetrievalMethod::kKdTree},
                                       {"ivf", RetrievalMethod::kIvf}}));
  f.push_back(integer<int>("retrieval.ivf_lists", "inverted-file lists (method ivf); 0: 2 sqrt(N)",
                           [](Config& c) -> int& { return c.retrieval.ivf_lists; }));
  f.push_back(integer<int>("retrieval.ivf_probe", "inverted-file lists scanned per query (method ivf)",
                           [](Config& c) -> int& { return c.retrieval.ivf_probe; }));
  f.push_back(integer<int>("retrieval.ivf_train_frames", "frames stored before the inverted file is trained",
                           [](Config& c) -> int& { return c.retrieval.ivf_train_frames; }));
  f.push_back(number("association.sigma_1", "σ_1: a slot matches iff cos(u, v) > σ_1",
                     [](Config& c) -> double& { return c.association.sigma_1; }));
  f.push_back(number("association.max_delta_aj", "... and |Δa_j| < this (m²)",
                     [](Config& c) -> double& { return c.association.max_delta_aj; }));
  f.push_back(number("association.sigma_2", "σ_2: accept the best node pair iff S >= σ_2",
                     [](Config& c) -> double& { return c.association.sigma_2; }));
  f.push_back(choice<NodeScore>("association.score", "node similarity S",
                                [](Config& c) -> NodeScore& { return c.association.score; },
                                {{"ratio", NodeScore::kRatio}, {"count", NodeScore::kCount}}));
  f.push_back(entriesField());
  f.push_back(number("verification.sigma_3", "σ_3: skip a candidate iff score_c < σ_3",
                     [](Config& c) -> double& { return c.verification.sigma_3; }));
  f.push_back(integer<int>("verification.min_associations", "... or |LA| < this",
                      [](Config& c) -> int& { return c.verification.min_associations; }));
  f.push_back(integer<int>("verification.ransac_iterations", "RANSAC hypotheses per candidate",
                      [](Config& c) -> int& { return c.verification.ransac_iterations; }));
  f.push_back(integer<int>("verification.ransac_sample_size", "node pairs per hypothesis",
                      [](Config& c) -> int& { return c.verification.ransac_sample_size; }));
  f.push_back(boolean("verification.sample_with_replacement", "draw pairs with replacement (authors' code)",
                      [](Config& c) -> bool& { return c.verification.sample_with_replacement; }));
  f.push_back(number("verification.inlier_threshold", "inlier iff ‖R s + t − t′‖ < this (m)",
                     [](Config& c) -> double& { return c.verification.inlier_threshold; }));
  f.push_back(integer<int>("verification.min_inliers", "accept a hypothesis only with >= this many inliers",
                      [](Config& c) -> int& { return c.verification.min_inliers; }));
  f.push_back(number("verification.min_inlier_fraction", "... and >= this share of |LA|",
                     [](Config& c) -> double& { return c.verification.min_inlier_fraction; }));
  f.push_back(boolean("verification.use_ransac", "false = score_c as the score, pose from all associations",
                      [](Config& c) -> bool& { return c.verification.use_ransac; }));
  f.push_back(number("verification.ransac_confidence",
                     "stop RANSAC once an all-inlier sample is drawn with this probability; 1 = all iterations",
                     [](Config& c) -> double& { return c.verification.ransac_confidence; }));
  f.push_back(choice<ScoreFormula>("verification.score_formula",
                                   "score: n_in/|LA|, (n_in - 1)/|LA| or n_in/max(M, N)",
                                   [](Config& c) -> ScoreFormula& { return c.verification.score_formula; },
                                   {{"paper", ScoreFormula::kPaper},
                                    {"legacy", ScoreFormula::kLegacy},
                                    {"overlap", ScoreFormula::kOverlap}}));
  f.push_back(number("verification.max_tilt_deg",
                     "RANSAC skips a rotation that tilts the up axis more than this (deg); 180 = no check",
                     [](Config& c) -> double& { return c.verification.max_tilt_deg; }));
  f.push_back(boolean("verification.guided_matching",
                      "after RANSAC, pair the nodes its pose puts together (score_formula overlap only)",
                      [](Config& c) -> bool& { return c.verification.guided_matching; }));
  f.push_back(integer<int>("verification.consistency_pairs",
                           "when the descriptors' pairs give no loop, verify the largest consistent set of each "
                           "query node's this many most similar same-class nodes; 0 = off",
                           [](Config& c) -> int& { return c.verification.consistency_pairs; }));
  f.push_back(integer<int>("verification.weak_inliers",
                           "a loop of at most this many inliers needs weak_min_footprint (0 = no such rule)",
                           [](Config& c) -> int& { return c.verification.weak_inliers; }));
  f.push_back(number("verification.weak_min_footprint",
                     "footprint share a loop of few inliers, or of the consistency path, needs",
                     [](Config& c) -> double& { return c.verification.weak_min_footprint; }));
  f.push_back(number("verification.sigma_4", "σ_4: loop iff best score > σ_4 (0.1 for MulRan/MCD)",
                     [](Config& c) -> double& { return c.verification.sigma_4; }));
  f.push_back(number("verification.select_margin",
                     "top-1: the nearest (smallest translation) of the candidates within this of the best score; 0 = best",
                     [](Config& c) -> double& { return c.verification.select_margin; }));
  f.push_back(number("verification.lateral_distance",
                     "a chosen candidate estimated this far or farther (m) is reported as lateral, not a revisit",
                     [](Config& c) -> double& { return c.verification.lateral_distance; }));
  f.push_back(integer<int>("verification.neighbour_frames",
                           "also verify the top-1 loop's database neighbours within this many frames; 0 = off",
                           [](Config& c) -> int& { return c.verification.neighbour_frames; }));
  f.push_back(number("verification.offset_decay_start",
                     "score is scaled down linearly for an estimated offset beyond this (m) ...",
                     [](Config& c) -> double& { return c.verification.offset_decay_start; }));
  f.push_back(number("verification.offset_decay_end", "... to 0 at this offset (m); 0 = no decay",
                     [](Config& c) -> double& { return c.verification.offset_decay_end; }));
  f.push_back(number("verification.min_footprint_overlap",
                     "reject a verified candidate whose pose puts less than this share of the query's structure "
                     "cells on the match's; 0 = off",
                     [](Config& c) -> double& { return c.verification.min_footprint_overlap; }));
  f.push_back(number("verification.footprint_cell", "side of a footprint cell (m)",
                     [](Config& c) -> double& { return c.verification.footprint_cell; }));
  f.push_back(number("verification.footprint_radius", "footprints reach this far from the sensor (m)",
                     [](Config& c) -> double& { return c.verification.footprint_radius; }));
  f.push_back(integer<uint32_t>("verification.seed", "RANSAC seed (std::mt19937)",
                                [](Config& c) -> uint32_t& { return c.verification.seed; }));
  addRegistrationFields(makers);
  f.push_back(integer<int>("threads", "worker threads for candidate verification; results do not depend on it",
                      [](Config& c) -> int& { return c.threads; }));
  addBackendFields(makers);
  return f;
}

}  // namespace sgtllc::io::detail
