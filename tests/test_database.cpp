// FrameDatabase (algorithm §5, §10): exact K-nearest-neighbour retrieval against a brute-force reference, for both
// search methods, with ties (duplicate descriptors) going to the lower frame index.
#include <algorithm>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include "sgtllc/database.h"

namespace {

using sgtllc::FrameDatabase;
using sgtllc::RetrievalMethod;
using sgtllc::StoredFrame;
using Rows = std::vector<std::vector<float>>;

constexpr int kDim = 98;
const RetrievalMethod kMethods[] = {RetrievalMethod::kBruteForce, RetrievalMethod::kKdTree};

std::string name(RetrievalMethod m) { return m == RetrievalMethod::kBruteForce ? "brute-force" : "kd-tree"; }

/// A random descriptor: small integers (exact squared distances, many ties) or uniform reals.
std::vector<float> randomDescriptor(std::mt19937& rng, bool integer) {
  std::uniform_int_distribution<int> small(0, 2);
  std::uniform_real_distribution<float> real(0.0f, 2.0f);
  std::vector<float> d(kDim);
  for (float& v : d) v = integer ? static_cast<float>(small(rng)) : real(rng);
  return d;
}

/// 300 frames; every 7th frame repeats an earlier one, so exact duplicates exist.
Rows makeRows(uint32_t seed, bool integer, int n = 300) {
  std::mt19937 rng(seed);
  Rows rows;
  for (int f = 0; f < n; ++f) {
    if (f > 0 && f % 7 == 0) {
      rows.push_back(rows[std::uniform_int_distribution<int>(0, f - 1)(rng)]);
    } else {
      rows.push_back(randomDescriptor(rng, integer));
    }
  }
  return rows;
}

StoredFrame frame(const std::vector<float>& global, int num_nodes = 0) {
  StoredFrame f;
  f.global = global;
  for (int k = 0; k < num_nodes; ++k) f.nodes.push_back(sgtllc::Node{Eigen::Vector3d(k, 2.0 * k, 1.0), k % 7});
  return f;
}

FrameDatabase makeDatabase(const Rows& rows, RetrievalMethod method) {
  FrameDatabase db(method);
  for (const auto& r : rows) db.add(frame(r));
  return db;
}

double distance2(const std::vector<float>& a, const std::vector<float>& b) {
  double d2 = 0.0;
  for (int d = 0; d < kDim; ++d) d2 += (static_cast<double>(a[d]) - b[d]) * (static_cast<double>(a[d]) - b[d]);
  return d2;
}

/// Every squared distance to frames 0..last, in double precision, sorted by (distance, index).
std::vector<std::pair<double, int>> bruteQuery(const Rows& rows, const std::vector<float>& q, int last, int k) {
  std::vector<std::pair<double, int>> all;
  for (int f = 0; f <= std::min(last, static_cast<int>(rows.size()) - 1); ++f) {
    all.emplace_back(distance2(rows[f], q), f);
  }
  std::sort(all.begin(), all.end());
  if (static_cast<int>(all.size()) > k) all.resize(k);
  return all;
}

/// The database sums in float, so distances may differ from the double reference by a few ulps and frames whose
/// distances differ by less than that may swap ranks. With small-integer descriptors every sum is exact, and the
/// frames must match rank for rank (ties to the lower index).
void expectSame(const std::vector<sgtllc::RetrievedFrame>& got, const std::vector<std::pair<double, int>>& want,
                const Rows& rows, const std::vector<float>& q, bool exact) {
  ASSERT_EQ(got.size(), want.size());
  for (size_t r = 0; r < want.size(); ++r) {
    const double tol = exact ? 0.0 : 1e-6 * std::max(1.0, want[r].first);
    if (exact) {
      EXPECT_EQ(got[r].frame, want[r].second) << "rank " << r;
    }
    EXPECT_NEAR(distance2(rows.at(got[r].frame), q), want[r].first, tol) << "rank " << r;
    EXPECT_NEAR(got[r].distance2, want[r].first, tol) << "rank " << r;
    for (size_t s = 0; s < r; ++s) EXPECT_NE(got[s].frame, got[r].frame) << "rank " << r;
  }
}

/// Queries: random descriptors plus copies of stored ones (distance 0, tied with their duplicates).
Rows makeQueries(const Rows& rows, uint32_t seed, bool integer) {
  std::mt19937 rng(seed);
  Rows queries;
  for (int k = 0; k < 30; ++k) queries.push_back(randomDescriptor(rng, integer));
  for (int f : {0, 3, 7, 14, 100, 133, 299}) queries.push_back(rows[f]);
  return queries;
}

TEST(FrameDatabase, QueryMatchesBruteForce) {
  for (bool integer : {true, false}) {
    const Rows rows = makeRows(integer ? 1 : 2, integer);
    const Rows queries = makeQueries(rows, 3, integer);
    for (RetrievalMethod method : kMethods) {
      SCOPED_TRACE(name(method) + (integer ? " integer" : " real"));
      const FrameDatabase db = makeDatabase(rows, method);
      // `last` first grows (the kd-tree extends), then shrinks (an older prefix than the tree holds).
      for (int last : {0, 1, 10, 99, 150, 299, 1000, 200, 42, 3}) {
        for (int k : {1, 3, 15, 500}) {
          for (size_t q = 0; q < queries.size(); ++q) {
            SCOPED_TRACE("last " + std::to_string(last) + " k " + std::to_string(k) + " query " + std::to_string(q));
            expectSame(db.query(queries[q], last, k), bruteQuery(rows, queries[q], last, k), rows, queries[q], integer);
          }
        }
      }
    }
  }
}

TEST(FrameDatabase, OnlineInsertThenQueryMatchesBruteForce) {
  // As the detector uses it: insert a frame, query the frames at least 50 older with K = 15.
  const Rows rows = makeRows(4, true);
  for (RetrievalMethod method : kMethods) {
    SCOPED_TRACE(name(method));
    FrameDatabase db(method);
    for (int f = 0; f < static_cast<int>(rows.size()); ++f) {
      const auto got = db.query(rows[f], f - 50, 15);
      ASSERT_NO_FATAL_FAILURE(expectSame(got, bruteQuery(rows, rows[f], f - 50, 15), rows, rows[f], true))
          << "frame " << f;
      ASSERT_EQ(db.add(frame(rows[f])), f);
    }
  }
}

TEST(FrameDatabase, TiesGoToTheLowerIndex) {
  std::mt19937 rng(5);
  const std::vector<float> dup = randomDescriptor(rng, false);
  Rows rows;
  for (int f = 0; f < 64; ++f) rows.push_back(f % 9 == 4 ? dup : randomDescriptor(rng, false));  // 4, 13, 22, …
  for (RetrievalMethod method : kMethods) {
    SCOPED_TRACE(name(method));
    const FrameDatabase db = makeDatabase(rows, method);
    for (int k : {1, 2, 3, 7}) {
      const auto got = db.query(dup, 63, k);
      ASSERT_EQ(static_cast<int>(got.size()), k);
      for (int r = 0; r < k; ++r) {
        EXPECT_EQ(got[r].frame, 4 + 9 * r) << "k " << k << " rank " << r;
        EXPECT_EQ(got[r].distance2, 0.0f);
      }
    }
    // All frames identical: the first k frames, in order.
    const FrameDatabase same = makeDatabase(Rows(40, dup), method);
    const auto got = same.query(dup, 39, 5);
    ASSERT_EQ(got.size(), 5u);
    for (int r = 0; r < 5; ++r) EXPECT_EQ(got[r].frame, r);
  }
}

TEST(FrameDatabase, EligibleRangeAndK) {
  const Rows rows = makeRows(6, false, 20);
  for (RetrievalMethod method : kMethods) {
    SCOPED_TRACE(name(method));
    const FrameDatabase db = makeDatabase(rows, method);
    EXPECT_TRUE(db.query(rows[0], -1, 15).empty());
    EXPECT_TRUE(db.query(rows[0], -50, 15).empty());
    const auto five = db.query(rows[3], 4, 15);  // k larger than the 5 eligible frames
    ASSERT_EQ(five.size(), 5u);
    EXPECT_EQ(five[0].frame, 3);
    for (const auto& r : five) EXPECT_LE(r.frame, 4);
    EXPECT_EQ(db.query(rows[3], 1000, 100).size(), 20u);  // last beyond the end: all frames
    EXPECT_TRUE(FrameDatabase(method).query(rows[0], 10, 15).empty());
  }
}

TEST(FrameDatabase, StoresFramesAndRejectsOtherLengths) {
  FrameDatabase db;
  std::mt19937 rng(7);
  const auto a = randomDescriptor(rng, false), b = randomDescriptor(rng, false);
  EXPECT_EQ(db.add(frame(a, 3)), 0);
  EXPECT_EQ(db.add(frame(b, 5)), 1);
  EXPECT_EQ(db.size(), 2);
  EXPECT_EQ(db.globalDimension(), kDim);
  EXPECT_EQ(std::vector<float>(db.global(1), db.global(1) + kDim), b);
  ASSERT_EQ(db.nodes(1).size(), 5u);
  EXPECT_EQ(db.nodes(1)[4].centre, Eigen::Vector3d(4, 8, 1));
  EXPECT_EQ(db.nodes(1)[4].label, 4);
  EXPECT_THROW(db.add(frame(std::vector<float>(343, 0.0f))), std::invalid_argument);
  EXPECT_THROW(db.add(frame(std::vector<float>(kDim - 1, 0.0f))), std::invalid_argument);
  EXPECT_EQ(db.size(), 2);
  EXPECT_EQ(db.query(a, 1, 1).front().frame, 0);  // still usable after the rejected adds
}

TEST(FrameDatabase, ByteAccounting) {
  FrameDatabase db;
  std::mt19937 rng(8);
  for (int nodes : {0, 10, 40, 10}) db.add(frame(randomDescriptor(rng, false), nodes));
  size_t sum = 0;
  for (int f = 0; f < db.size(); ++f) {
    EXPECT_GE(db.frameBytes(f), db.nodes(f).size() * sizeof(sgtllc::Node) + kDim * sizeof(float)) << f;
    sum += db.frameBytes(f);
  }
  EXPECT_EQ(db.totalBytes(), sum);
  EXPECT_LT(db.frameBytes(0), db.frameBytes(1));
  EXPECT_LT(db.frameBytes(1), db.frameBytes(2));
  EXPECT_EQ(FrameDatabase().totalBytes(), 0u);
  // A k-d tree, once a query builds it, is counted beside the frames, and grows with them by at least a row index
  // and a tree number (two 4-byte integers) per frame.
  const Rows rows = makeRows(10, false, 600);
  FrameDatabase tree(RetrievalMethod::kKdTree);
  for (int f = 0; f < 100; ++f) tree.add(frame(rows[f], 3));
  EXPECT_EQ(tree.searchBytes(), 0u);
  tree.query(rows[0], 99, 2);
  const size_t small = tree.searchBytes();
  EXPECT_GT(small, 0u);
  for (int f = 100; f < 600; ++f) tree.add(frame(rows[f], 3));
  tree.query(rows[0], 599, 2);
  EXPECT_GE(tree.searchBytes(), small + 500 * 2 * sizeof(uint32_t));
  size_t frames = 0;
  for (int f = 0; f < tree.size(); ++f) frames += tree.frameBytes(f);
  EXPECT_EQ(tree.totalBytes(), frames + tree.searchBytes());
}

// A copy answers every query as the original, with either exact method (the tree is rebuilt at its first query),
// keeps the method, and grows apart from the original.
TEST(FrameDatabase, ACopyAnswersAsTheOriginal) {
  const Rows rows = makeRows(11, false, 200);
  for (RetrievalMethod method : kMethods) {
    FrameDatabase db = makeDatabase(rows, method);
    db.query(rows[3], 199, 5);  // the original's tree built before the copy
    FrameDatabase copy = db.copy();
    EXPECT_EQ(copy.size(), 200);
    EXPECT_EQ(copy.searchBytes(), 0u);  // nothing built yet
    for (int q = 0; q < 200; q += 37) {
      const auto a = copy.query(rows[q], 199, 7), b = db.query(rows[q], 199, 7);
      ASSERT_EQ(a.size(), b.size());
      for (size_t i = 0; i < a.size(); ++i) {
        EXPECT_EQ(a[i].frame, b[i].frame);
        EXPECT_EQ(a[i].distance2, b[i].distance2);
      }
    }
    EXPECT_EQ(copy.searchBytes() > 0, method == RetrievalMethod::kKdTree);
    copy.add(frame(rows[0], 2));
    EXPECT_EQ(copy.size(), 201);
    EXPECT_EQ(db.size(), 200);
    for (int f = 0; f < 200; ++f) EXPECT_EQ(copy.nodes(f).size(), db.nodes(f).size());
  }
}

TEST(FrameDatabase, MovedDatabaseKeepsItsFrames) {
  const Rows rows = makeRows(9, false, 30);
  for (RetrievalMethod method : kMethods) {
    FrameDatabase db = makeDatabase(rows, method);
    const auto before = db.query(rows[5], 29, 4);  // builds the kd-tree before the move
    FrameDatabase moved(std::move(db));
    EXPECT_EQ(moved.size(), 30);
    expectSame(moved.query(rows[5], 29, 4), bruteQuery(rows, rows[5], 29, 4), rows, rows[5], false);
    ASSERT_EQ(before.size(), 4u);
  }
}

}  // namespace
