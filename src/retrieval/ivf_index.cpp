#include "retrieval/ivf_index.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "internal/squared_distance.h"
#include "sgtllc/parallel.h"
#include "sgtllc/types.h"

#ifdef SGTLLC_HAVE_FAISS
#include <faiss/Clustering.h>
#include <faiss/IndexFlat.h>
#endif

namespace sgtllc::internal {
namespace {

/// Nearer first, ties to the lower id: the linear scan's order.
bool closer(const std::pair<int, float>& a, const std::pair<int, float>& b) {
  return a.second < b.second || (a.second == b.second && a.first < b.first);
}

#ifdef SGTLLC_HAVE_FAISS
/// Lists for @p rows frames when RetrievalConfig::ivf_lists is 0: 2·√N keeps a list near √N/2 frames, so a query
/// scanning ivf_probe lists reads a few thousand keys at a million frames (BENCHMARKS.md "Retrieval at scale").
int automaticLists(int rows) {
  return std::clamp(static_cast<int>(std::lround(2.0 * std::sqrt(static_cast<double>(rows)))), 16, 16384);
}
#endif

}  // namespace

bool ivfAvailable() {
#ifdef SGTLLC_HAVE_FAISS
  return true;
#else
  return false;
#endif
}

IvfIndex::IvfIndex(const std::vector<float>* rows, int dim, const RetrievalConfig& config, int threads)
    : rows_(rows), dim_(dim), config_(config), threads_(std::max(1, threads)) {}

int IvfIndex::nearestList(const float* row) const {
  int best = 0;
  float best_d2 = squaredDistance(row, state_.centroids.data(), dim_);
  for (int l = 1; l < state_.lists; ++l) {
    const float d2 = squaredDistance(row, state_.centroids.data() + static_cast<size_t>(l) * dim_, dim_);
    if (d2 < best_d2) best = l, best_d2 = d2;
  }
  return best;
}

void IvfIndex::train() {
#ifdef SGTLLC_HAVE_FAISS
  const int rows = static_cast<int>(rows_->size() / dim_);
  const int lists = config_.ivf_lists > 0 ? std::min(config_.ivf_lists, rows) : automaticLists(rows);
  faiss::ClusteringParameters params;
  params.niter = 12;
  params.seed = 20250101;  // fixed: the same rows give the same centroids
  // 64 sampled keys per centroid settle the centroids as well as FAISS's default 256 on the benchmark's keys at a
  // quarter of the cost (BENCHMARKS.md "Retrieval at scale").
  params.max_points_per_centroid = 64;
  params.min_points_per_centroid = 1;  // 2·√N lists leave √N/2 keys per centroid, on purpose (and FAISS stays quiet)
  faiss::Clustering clustering(dim_, lists, params);
  faiss::IndexFlatL2 assigner(dim_);
  clustering.train(static_cast<faiss::Index::idx_t>(rows), rows_->data(), assigner);
  state_.lists = lists;
  state_.trained_frames = rows;
  state_.centroids.assign(clustering.centroids.begin(), clustering.centroids.end());
  state_.list_of_frame.clear();
#else
  throw Error("retrieval.method ivf: this build of sgtllc has no FAISS (configure with libfaiss-dev installed)");
#endif
}

void IvfIndex::update() {
  const int rows = static_cast<int>(rows_->size() / dim_);
  const bool first = !trained() && rows >= config_.ivf_train_frames;
  const bool regrow = trained() && config_.ivf_lists == 0 && rows >= 4 * static_cast<long long>(state_.trained_frames);
  if (first || regrow) train();
  if (!trained() || rows == size()) return;
  const int from = size();
  state_.list_of_frame.resize(rows);
  parallelFor(rows - from, threads_, [&](int i) {
    const int f = from + i;
    state_.list_of_frame[f] = nearestList(rows_->data() + static_cast<size_t>(f) * dim_);
  });
  if (from == 0) {
    rebuildLists();
  } else {
    for (int f = from; f < rows; ++f) lists_[state_.list_of_frame[f]].push_back(f);
  }
}

void IvfIndex::rebuildLists() {
  lists_.assign(state_.lists, {});
  for (int f = 0; f < size(); ++f) lists_[state_.list_of_frame[f]].push_back(f);
}

void IvfIndex::knn(const float* query, int last, int k, int probe, std::vector<std::pair<int, float>>* out) const {
  std::vector<std::pair<int, float>> centres(state_.lists);
  for (int l = 0; l < state_.lists; ++l) {
    centres[l] = {l, squaredDistance(query, state_.centroids.data() + static_cast<size_t>(l) * dim_, dim_)};
  }
  const size_t scan = std::min(centres.size(), static_cast<size_t>(probe));
  std::partial_sort(centres.begin(), centres.begin() + scan, centres.end(), closer);
  std::vector<std::pair<int, float>> hits;
  const size_t row_bytes = static_cast<size_t>(dim_) * sizeof(float);
  for (size_t c = 0; c < scan; ++c) {
    const std::vector<int32_t>& list = lists_[centres[c].first];
    for (size_t i = 0; i < list.size() && list[i] <= last; ++i) {  // lists are ascending
      // A list's frames lie far apart in the key matrix: fetch the next one's key while this one is compared.
      if (i + 1 < list.size()) {
        const char* next = reinterpret_cast<const char*>(rows_->data() + static_cast<size_t>(list[i + 1]) * dim_);
        for (size_t b = 0; b < row_bytes; b += 64) __builtin_prefetch(next + b);
      }
      hits.emplace_back(list[i], squaredDistance(rows_->data() + static_cast<size_t>(list[i]) * dim_, query, dim_));
    }
  }
  const size_t keep = std::min(hits.size(), static_cast<size_t>(k));
  std::partial_sort(hits.begin(), hits.begin() + keep, hits.end(), closer);
  out->insert(out->end(), hits.begin(), hits.begin() + keep);
}

void IvfIndex::restore(IvfState state) {
  const size_t rows = rows_->size() / dim_;
  if (state.lists < 1 || state.centroids.size() != static_cast<size_t>(state.lists) * dim_) {
    throw std::invalid_argument("inverted file: centroids do not match the list count and key length");
  }
  if (state.list_of_frame.size() > rows || state.trained_frames < 1 ||
      static_cast<size_t>(state.trained_frames) > rows) {
    throw std::invalid_argument("inverted file: more indexed frames than stored frames");
  }
  for (int32_t l : state.list_of_frame) {
    if (l < 0 || l >= state.lists) throw std::invalid_argument("inverted file: a frame's list is out of range");
  }
  state_ = std::move(state);
  rebuildLists();
}

}  // namespace sgtllc::internal
