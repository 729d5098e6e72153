#include "sgtllc/database.h"

#include <algorithm>
#include <stdexcept>
#include <utility>

#include "internal/squared_distance.h"
#include "kdtree_index.h"
#include "retrieval/ivf_index.h"

namespace sgtllc {

using internal::squaredDistance;

struct FrameDatabase::Impl {
  RetrievalMethod method;
  RetrievalConfig retrieval;  ///< the inverted file's parameters (kIvf)
  int threads = 1;
  std::vector<std::vector<Node>> nodes;
  std::vector<float> globals;  ///< row-major, one row per frame
  int dim = -1;
  std::unique_ptr<internal::KdTreeIndex> kdtree;  ///< built lazily for kKdTree
  std::unique_ptr<internal::IvfIndex> ivf;        ///< made at the first query for kIvf

  internal::IvfIndex& ivfIndex() {
    if (!ivf) ivf = std::make_unique<internal::IvfIndex>(&globals, dim, retrieval, threads);
    return *ivf;
  }
};

FrameDatabase::FrameDatabase(RetrievalMethod method) : impl_(std::make_unique<Impl>()) { impl_->method = method; }
FrameDatabase::FrameDatabase(const RetrievalConfig& retrieval, int threads) : FrameDatabase(retrieval.method) {
  impl_->retrieval = retrieval;
  impl_->threads = threads;
}
FrameDatabase::~FrameDatabase() = default;
FrameDatabase::FrameDatabase(FrameDatabase&&) noexcept = default;
FrameDatabase& FrameDatabase::operator=(FrameDatabase&&) noexcept = default;

FrameDatabase FrameDatabase::copy() const {
  FrameDatabase out(impl_->retrieval, impl_->threads);
  out.impl_->method = impl_->method;
  if (size() > 0) out.assign(impl_->nodes, std::vector<float>(impl_->globals));  // a copy's capacity is its size
  if (std::optional<IvfState> ivf = ivfState()) out.restoreIvf(std::move(*ivf));
  return out;
}

void FrameDatabase::setSearch(const RetrievalConfig& retrieval, int threads) {
  std::optional<IvfState> kept = ivfState();
  impl_->method = retrieval.method;
  impl_->retrieval = retrieval;
  impl_->threads = threads;
  impl_->kdtree.reset();
  impl_->ivf.reset();
  if (kept && retrieval.method == RetrievalMethod::kIvf) impl_->ivfIndex().restore(std::move(*kept));
}

int FrameDatabase::size() const { return static_cast<int>(impl_->nodes.size()); }
const std::vector<Node>& FrameDatabase::nodes(int index) const { return impl_->nodes.at(index); }
const float* FrameDatabase::global(int index) const {
  if (index < 0 || index >= size()) throw std::out_of_range("FrameDatabase::global: no such frame");
  return impl_->globals.data() + static_cast<size_t>(index) * impl_->dim;
}
int FrameDatabase::globalDimension() const { return impl_->dim; }

int FrameDatabase::add(StoredFrame frame) {
  const int dim = static_cast<int>(frame.global.size());
  if (impl_->dim < 0) impl_->dim = dim;
  if (dim != impl_->dim) throw std::invalid_argument("FrameDatabase::add: global descriptor length changed");
  impl_->globals.insert(impl_->globals.end(), frame.global.begin(), frame.global.end());
  impl_->nodes.push_back(std::move(frame.nodes));
  return size() - 1;
}

void FrameDatabase::assign(std::vector<std::vector<Node>> nodes, std::vector<float> globals) {
  if (size() != 0) throw std::invalid_argument("FrameDatabase::assign: the database is not empty");
  if (nodes.empty() != globals.empty() || (!nodes.empty() && globals.size() % nodes.size() != 0)) {
    throw std::invalid_argument("FrameDatabase::assign: the keys do not divide evenly among the frames");
  }
  if (nodes.empty()) return;
  impl_->dim = static_cast<int>(globals.size() / nodes.size());
  impl_->globals = std::move(globals);
  impl_->nodes = std::move(nodes);
  impl_->kdtree.reset();
  impl_->ivf.reset();
}

std::vector<RetrievedFrame> FrameDatabase::query(const std::vector<float>& global, int last, int k) const {
  std::vector<RetrievedFrame> out;
  last = std::min(last, size() - 1);
  if (last < 0 || k <= 0) return out;
  if (static_cast<int>(global.size()) != impl_->dim) {
    throw std::invalid_argument("FrameDatabase::query: global descriptor length differs from the stored ones");
  }
  std::vector<std::pair<int, float>> hits;
  if (impl_->method == RetrievalMethod::kIvf) {
    internal::IvfIndex& ivf = impl_->ivfIndex();
    ivf.update();
    if (ivf.trained()) {
      ivf.knn(global.data(), last, k, impl_->retrieval.ivf_probe, &hits);
      for (const auto& [f, d2] : hits) out.push_back(RetrievedFrame{f, d2});
      return out;
    }
  }
  // The tree only grows; a query over an older prefix than it holds falls back to the exact scan.
  if (impl_->method == RetrievalMethod::kKdTree && (!impl_->kdtree || impl_->kdtree->size() <= last + 1)) {
    if (!impl_->kdtree) impl_->kdtree = std::make_unique<internal::KdTreeIndex>(&impl_->globals, impl_->dim);
    impl_->kdtree->extendTo(last);
    impl_->kdtree->knn(global.data(), k, &hits);
  } else {
    hits.reserve(static_cast<size_t>(last) + 1);
    for (int f = 0; f <= last; ++f) {
      hits.emplace_back(f, squaredDistance(impl_->globals.data() + static_cast<size_t>(f) * impl_->dim,
                                           global.data(), impl_->dim));
    }
    const auto closer = [](const auto& a, const auto& b) {
      return a.second < b.second || (a.second == b.second && a.first < b.first);
    };
    const size_t keep = std::min(hits.size(), static_cast<size_t>(k));
    std::partial_sort(hits.begin(), hits.begin() + keep, hits.end(), closer);
    hits.resize(keep);
  }
  for (const auto& [f, d2] : hits) out.push_back(RetrievedFrame{f, d2});
  return out;
}

std::optional<IvfState> FrameDatabase::ivfState() const {
  if (!impl_->ivf || !impl_->ivf->trained()) return std::nullopt;
  return impl_->ivf->state();
}

void FrameDatabase::restoreIvf(IvfState state) {
  if (impl_->method != RetrievalMethod::kIvf) {
    throw std::invalid_argument("FrameDatabase::restoreIvf: the database does not search with an inverted file");
  }
  if (impl_->dim < 0) throw std::invalid_argument("FrameDatabase::restoreIvf: the database has no frames");
  impl_->ivfIndex().restore(std::move(state));
}

size_t FrameDatabase::frameBytes(int index) const {
  return sizeof(std::vector<Node>) + impl_->nodes.at(index).capacity() * sizeof(Node) +
         static_cast<size_t>(impl_->dim) * sizeof(float);
}

size_t FrameDatabase::searchBytes() const {
  size_t bytes = 0;
  if (impl_->ivf) bytes += impl_->ivf->bytes();
  if (impl_->kdtree) bytes += impl_->kdtree->bytes();
  return bytes;
}

size_t FrameDatabase::totalBytes() const {
  size_t bytes = searchBytes();
  for (int f = 0; f < size(); ++f) bytes += frameBytes(f);
  return bytes;
}

}  // namespace sgtllc
