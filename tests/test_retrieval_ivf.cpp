// retrieval.method: ivf (algorithm §5 "Retrieval at scale"): the inverted file against the exact scan on 10,000
// frames cropped from the bundled real scans' nodes — the exact scan until it trains, then at least 0.99 of the exact
// top-15 with the exact distances; the same at 1 and 2 threads; a saved state restores the same answers.
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <random>
#include <set>

#include <gtest/gtest.h>

#include "retrieval/ivf_index.h"
#include "sgtllc/database.h"
#include "sgtllc/map/map_file.h"
#include "sgtllc/map/map_format.h"
#include "sgtllc/node_extraction.h"
#include "test_places_support.h"
#include "test_kitti_support.h"

namespace {

using namespace sgtllc;

/// The nodes of the four bundled KITTI 00 scans.
const std::vector<std::vector<Node>>& realFrames() {
  static const std::vector<std::vector<Node>> frames = [] {
    const NodeExtractor extractor(Config{}.cluster, Config{}.labels);
    std::vector<std::vector<Node>> out;
    for (const char* f : {"000052", "004501", "000088", "000850"}) out.push_back(extractor.extract(test::kittiScan(f)).nodes);
    return out;
  }();
  return frames;
}

/// @p places places, @p visits visits each (frames of one place are consecutive), and one more visit of every
/// fifth place as a query.
struct Scene {
  std::vector<std::vector<float>> frames;
  std::vector<std::vector<float>> queries;
};

const Scene& scene() {
  static const Scene s = [] {
    const Config c;
    std::mt19937 rng(2026);
    Scene out;
    for (int p = 0; p < 2000; ++p) {
      const std::vector<Node> place = test::cropPlace(realFrames()[p % 4], rng);
      for (int v = 0; v < 5; ++v) out.frames.push_back(test::keyOf(test::visit(place, rng), c));
      if (p % 10 == 0) out.queries.push_back(test::keyOf(test::visit(place, rng), c));
    }
    return out;
  }();
  return s;
}

RetrievalConfig ivfConfig(int train_frames) {
  RetrievalConfig r;
  r.method = RetrievalMethod::kIvf;
  r.ivf_train_frames = train_frames;
  return r;
}

/// The first @p frames frames, with a query after every 500th as the online detector queries as it goes (the
/// inverted file trains and grows at queries).
FrameDatabase fill(const RetrievalConfig& r, int threads, size_t frames) {
  FrameDatabase db(r, threads);
  for (size_t f = 0; f < frames; ++f) {
    db.add(StoredFrame{{}, scene().frames[f]});
    if ((f + 1) % 500 == 0) db.query(scene().queries[0], static_cast<int>(f), 15);
  }
  return db;
}

bool sameHits(const std::vector<RetrievedFrame>& a, const std::vector<RetrievedFrame>& b) {
  return std::equal(a.begin(), a.end(), b.begin(), b.end(), [](const RetrievedFrame& x, const RetrievedFrame& y) {
    return x.frame == y.frame && x.distance2 == y.distance2;
  });
}

class IvfSearch : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!internal::ivfAvailable()) GTEST_SKIP() << "this build has no FAISS (SGTLLC_WITH_FAISS=OFF)";
  }
};

TEST_F(IvfSearch, IsTheExactScanUntilTrained) {
  const FrameDatabase exact = fill(RetrievalConfig{}, 1, 900);
  const FrameDatabase ivf = fill(ivfConfig(1000), 1, 900);
  for (const auto& q : scene().queries) EXPECT_TRUE(sameHits(ivf.query(q, 899, 15), exact.query(q, 899, 15)));
  EXPECT_FALSE(ivf.ivfState().has_value());
}

// The database's bytes count the inverted file beside the frames: at least a one-byte code per key value once the
// lists are coded, and the centroids' floats; the linear scan holds nothing beside its frames.
TEST_F(IvfSearch, ByteAccountingCountsTheListsAndCodes) {
  const FrameDatabase exact = fill(RetrievalConfig{}, 1, 3000);
  const FrameDatabase ivf = fill(ivfConfig(1000), 1, 3000);
  EXPECT_EQ(exact.searchBytes(), 0u);
  const size_t dim = static_cast<size_t>(ivf.globalDimension());
  const IvfState state = *ivf.ivfState();
  EXPECT_GE(ivf.searchBytes(), 3000 * dim + state.centroids.size() * sizeof(float) + 3000 * sizeof(int32_t));
  EXPECT_LT(ivf.searchBytes(), 2 * (3000 * dim + state.centroids.size() * sizeof(float)) + 3000 * 16);
  size_t frames = 0;
  for (int f = 0; f < ivf.size(); ++f) frames += ivf.frameBytes(f);
  EXPECT_EQ(ivf.totalBytes(), frames + ivf.searchBytes());
}

// A copy keeps the trained inverted file (Python's Map and relocalizer copy maps this way) and answers every query
// as the original; adding to the copy leaves the original as it was.
TEST_F(IvfSearch, ACopyKeepsTheTrainedIndex) {
  const FrameDatabase ivf = fill(ivfConfig(1000), 1, 3000);
  FrameDatabase copy = ivf.copy();
  ASSERT_TRUE(copy.ivfState().has_value());
  EXPECT_EQ(copy.ivfState()->centroids, ivf.ivfState()->centroids);
  EXPECT_EQ(copy.ivfState()->list_of_frame, ivf.ivfState()->list_of_frame);
  for (const auto& q : scene().queries) EXPECT_TRUE(sameHits(copy.query(q, 2999, 15), ivf.query(q, 2999, 15)));
  copy.add(StoredFrame{{}, scene().frames[3000]});
  EXPECT_EQ(copy.size(), 3001);
  EXPECT_EQ(ivf.size(), 3000);
  EXPECT_EQ(ivf.ivfState()->list_of_frame.size(), 3000u);
  // Untrained, the copy is the exact scan as the original is, and trains as the original would.
  const FrameDatabase untrained = fill(ivfConfig(1000), 1, 900);
  FrameDatabase untrained_copy = untrained.copy();
  EXPECT_FALSE(untrained_copy.ivfState().has_value());
  for (const auto& q : scene().queries) {
    EXPECT_TRUE(sameHits(untrained_copy.query(q, 899, 15), untrained.query(q, 899, 15)));
  }
  for (size_t f = 900; f < 1000; ++f) untrained_copy.add(StoredFrame{{}, scene().frames[f]});
  const FrameDatabase trained = fill(ivfConfig(1000), 1, 1000);
  untrained_copy.query(scene().queries[0], 999, 15);
  trained.query(scene().queries[0], 999, 15);
  ASSERT_TRUE(untrained_copy.ivfState().has_value());
  EXPECT_EQ(untrained_copy.ivfState()->centroids, trained.ivfState()->centroids);
}

TEST_F(IvfSearch, FindsTheExactTop15WithExactDistances) {
  const size_t n = scene().frames.size();
  const FrameDatabase exact = fill(RetrievalConfig{}, 1, n);
  const FrameDatabase ivf = fill(ivfConfig(2000), 2, n);
  long found = 0;
  long wanted = 0;
  for (int last : {static_cast<int>(n) - 1, 4999}) {
    for (const auto& q : scene().queries) {
      const auto truth = exact.query(q, last, 15);
      const auto hits = ivf.query(q, last, 15);
      ASSERT_EQ(hits.size(), 15u);
      for (const RetrievedFrame& h : hits) {
        EXPECT_LE(h.frame, last);
        const auto same = std::find_if(truth.begin(), truth.end(), [&](const RetrievedFrame& t) { return t.frame == h.frame; });
        if (same != truth.end()) {
          EXPECT_EQ(same->distance2, h.distance2);
        }
        found += same != truth.end();
      }
      wanted += static_cast<long>(truth.size());
    }
  }
  // Trained at 2,000 frames and again at 8,000 (fourfold growth, ivf_lists 0): 2·√8000 ≈ 179 lists.
  const auto state = ivf.ivfState();
  ASSERT_TRUE(state.has_value());
  EXPECT_EQ(state->trained_frames, 8000);
  EXPECT_EQ(state->lists, 179);
  EXPECT_EQ(state->list_of_frame.size(), n);
  EXPECT_GE(static_cast<double>(found) / wanted, 0.99) << found << " of " << wanted;
}

TEST_F(IvfSearch, SameAtAnyThreadCountAndAfterRestore) {
  const size_t n = 6000;
  const FrameDatabase one = fill(ivfConfig(3000), 1, n);
  const FrameDatabase two = fill(ivfConfig(3000), 2, n);
  for (const auto& q : scene().queries) ASSERT_TRUE(sameHits(one.query(q, n - 1, 15), two.query(q, n - 1, 15)));
  const IvfState state = *one.ivfState();
  EXPECT_EQ(state.centroids, two.ivfState()->centroids);
  EXPECT_EQ(state.list_of_frame, two.ivfState()->list_of_frame);

  FrameDatabase restored = fill(ivfConfig(3000), 1, n);
  restored.restoreIvf(state);
  for (const auto& q : scene().queries) EXPECT_TRUE(sameHits(restored.query(q, n - 1, 15), one.query(q, n - 1, 15)));
}

TEST_F(IvfSearch, RefusesAStateThatDoesNotFit) {
  FrameDatabase db = fill(ivfConfig(3000), 1, 4000);
  db.query(scene().queries[0], 3999, 15);
  const IvfState good = *db.ivfState();
  IvfState bad_list = good;
  bad_list.list_of_frame[7] = good.lists;
  EXPECT_THROW(db.restoreIvf(bad_list), std::invalid_argument);
  IvfState short_centroids = good;
  short_centroids.centroids.pop_back();
  EXPECT_THROW(db.restoreIvf(short_centroids), std::invalid_argument);
  IvfState too_many = good;
  too_many.list_of_frame.resize(4001, 0);
  EXPECT_THROW(db.restoreIvf(too_many), std::invalid_argument);
  FrameDatabase exact = fill(RetrievalConfig{}, 1, 10);
  EXPECT_THROW(exact.restoreIvf(good), std::invalid_argument);
}

}  // namespace

namespace {

TEST_F(IvfSearch, AMapFileCarriesTheTrainedIndex) {
  Config config;
  config.retrieval = ivfConfig(3000);
  const FrameDatabase db = fill(config.retrieval, 1, 4000);
  std::vector<std::string> names;
  for (int f = 0; f < db.size(); ++f) names.push_back(std::to_string(f));
  const map::Map made = map::makeMap(db, config, names);
  const std::string bytes = map::encodeMap(made);
  // The file is written from the map's pieces (its keys straight from the database): the same bytes.
  const std::string file = (std::filesystem::path(::testing::TempDir()) /
                            ("sgtllc_ivf_" + std::to_string(::getpid()) + ".sgtmap")).string();
  map::writeMapFile(file, made, io::Overwrite::kReplace);
  std::ifstream in(file, std::ios::binary);
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(in), {}), bytes);
  std::filesystem::remove(file);
  const map::Map loaded = map::decodeMap(bytes, "ivf.sgtmap", RetrievalMethod::kIvf);
  ASSERT_TRUE(loaded.database.ivfState().has_value());
  EXPECT_EQ(loaded.database.ivfState()->centroids, db.ivfState()->centroids);
  EXPECT_EQ(loaded.database.ivfState()->list_of_frame, db.ivfState()->list_of_frame);
  for (const auto& q : scene().queries) EXPECT_TRUE(sameHits(loaded.database.query(q, 3999, 15), db.query(q, 3999, 15)));
  // Searched exactly, the same map has no inverted file, and re-encoding it drops the section.
  const map::Map exact = map::decodeMap(bytes, "ivf.sgtmap", RetrievalMethod::kBruteForce);
  EXPECT_FALSE(exact.database.ivfState().has_value());
  EXPECT_LT(map::encodeMap(exact).size(), bytes.size());
}

}  // namespace
