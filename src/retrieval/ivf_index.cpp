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
  coded_ = false;
#else
  throw Error("retrieval.method ivf: this build of sgtllc has no FAISS (configure with libfaiss-dev installed)");
#endif
}

void IvfIndex::update() {
  const int rows = static_cast<int>(rows_->size() / dim_);
  const bool first = !trained() && rows >= config_.ivf_train_frames;
  const bool regrow = trained() && config_.ivf_lists == 0 && rows >= 4 * static_cast<long long>(state_.trained_frames);
  if (first || regrow) train();
  if (!trained()) return;
  if (rows != size()) {
    const int from = size();
    state_.list_of_frame.resize(rows);
    parallelFor(rows - from, threads_, [&](int i) {
      const int f = from + i;
      state_.list_of_frame[f] = nearestList(rows_->data() + static_cast<size_t>(f) * dim_);
    });
    if (from == 0) {
      rebuildLists();
    } else {
      try {
        for (int f = from; f < rows; ++f) {
          const int list = state_.list_of_frame[f];
          lists_[list].push_back(f);
          if (coded_) codes_.encode(rows_->data() + static_cast<size_t>(f) * dim_, &list_codes_[list]);
        }
      } catch (...) {
        coded_ = false;  // lists and codes may disagree now (out of memory): the next update encodes them anew
        throw;
      }
    }
  }
  if (!coded_) encodeLists();
}

void IvfIndex::rebuildLists() {
  std::vector<size_t> count(state_.lists, 0);
  for (int32_t l : state_.list_of_frame) ++count[l];
  lists_.assign(state_.lists, {});
  for (int l = 0; l < state_.lists; ++l) lists_[l].reserve(count[l]);
  for (int f = 0; f < size(); ++f) lists_[state_.list_of_frame[f]].push_back(f);
  coded_ = false;
}

void IvfIndex::encodeLists() {
  codes_ = ScalarCodes(rows_->data(), state_.trained_frames, dim_);  // the rows the centroids were trained on
  list_codes_.assign(state_.lists, {});
  for (int l = 0; l < state_.lists; ++l) {
    std::vector<uint8_t>& codes = list_codes_[l];
    codes.reserve(lists_[l].size() * static_cast<size_t>(dim_));  // exact: a million default keys code to 840 MB
    for (int32_t f : lists_[l]) codes_.encode(rows_->data() + static_cast<size_t>(f) * dim_, &codes);
  }
  coded_ = true;
}

void IvfIndex::knn(const float* query, int last, int k, int probe, std::vector<std::pair<int, float>>* out) const {
  if (!coded_) throw std::logic_error("IvfIndex::knn: update() has not made the codes since the last restore()");
  std::vector<std::pair<int, float>> centres(state_.lists);
  for (int l = 0; l < state_.lists; ++l) {
    centres[l] = {l, squaredDistance(query, state_.centroids.data() + static_cast<size_t>(l) * dim_, dim_)};
  }
  const size_t scan = std::min(centres.size(), static_cast<size_t>(probe));
  std::partial_sort(centres.begin(), centres.begin() + scan, centres.end(), closer);
  std::vector<std::pair<uint32_t, int>> estimates;  // (code distance, row): integers, exact at any size
  std::vector<uint8_t> query_code;
  codes_.encode(query, &query_code);
  for (size_t c = 0; c < scan; ++c) {
    const std::vector<int32_t>& list = lists_[centres[c].first];
    const uint8_t* code = list_codes_[centres[c].first].data();
    for (size_t i = 0; i < list.size() && list[i] <= last; ++i, code += dim_) {  // lists are ascending
      estimates.emplace_back(ScalarCodes::distance(query_code.data(), code, dim_), list[i]);
    }
  }
  // The nearest estimates, then their exact distances; the order (estimate, row) is total, so the frames kept do
  // not depend on the order the lists were scanned in.
  const size_t compared =
      std::min(estimates.size(), static_cast<size_t>(kRerank) * static_cast<size_t>(std::max(k, 0)));
  std::nth_element(estimates.begin(), estimates.begin() + compared, estimates.end());
  std::vector<std::pair<int, float>> hits(compared);
  const size_t row_bytes = static_cast<size_t>(dim_) * sizeof(float);
  for (size_t i = 0; i < compared; ++i) {
    // The frames lie far apart in the key matrix: fetch the next one's key while this one is compared.
    if (i + 1 < compared) {
      const size_t next_row = static_cast<size_t>(estimates[i + 1].second);
      const char* next = reinterpret_cast<const char*>(rows_->data() + next_row * dim_);
      for (size_t b = 0; b < row_bytes; b += 64) __builtin_prefetch(next + b);
    }
    const int row = estimates[i].second;
    hits[i] = {row, squaredDistance(rows_->data() + static_cast<size_t>(row) * dim_, query, dim_)};
  }
  const size_t keep = std::min(hits.size(), static_cast<size_t>(k));
  std::partial_sort(hits.begin(), hits.begin() + keep, hits.end(), closer);
  out->insert(out->end(), hits.begin(), hits.begin() + keep);
}

size_t IvfIndex::bytes() const {
  size_t bytes = sizeof(IvfIndex) + state_.centroids.capacity() * sizeof(float) +
                 state_.list_of_frame.capacity() * sizeof(int32_t);
  for (const auto& list : lists_) bytes += sizeof(list) + list.capacity() * sizeof(int32_t);
  for (const auto& codes : list_codes_) bytes += sizeof(codes) + codes.capacity();
  return bytes;
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
  rebuildLists();  // the codes wait for the first query: a map being copied or written needs none
}

}  // namespace sgtllc::internal
