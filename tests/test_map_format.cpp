// The map file format (docs/map-format.md): exact round trips, a resumed detector equal to one run,
// relocalization from a loaded map equal to the in-memory one, and clean failures for every damaged byte and
// every truncation.
#include <gtest/gtest.h>

#include <cstring>
#include <zlib.h>

#include "sgtllc/map/map_format.h"
#include "sgtllc/map/relocalizer.h"
#include "test_map_support.h"
#include "test_kitti_support.h"

namespace sgtllc {
namespace {

using map::Map;
using map::MapError;
using map::MapProblem;

Config mapTestConfig(int threads = 1) {
  Config config;
  config.retrieval.exclude_recent = 20;
  config.threads = threads;
  return config;
}

Map mapOf(const test::NodeSequence& s, const Config& config, bool poses = true) {
  const LoopDetector detector = test::runNodes(s, config);
  return map::makeMap(detector.database(), config, s.names, poses ? s.poses : std::vector<Eigen::Matrix4d>{});
}

MapProblem problemOf(std::string_view bytes, std::string* message = nullptr) {
  try {
    map::decodeMap(bytes, "m.sgtmap");
  } catch (const MapError& e) {
    if (message) *message = e.what();
    return e.problem();
  }
  ADD_FAILURE() << "decoded";
  return MapProblem::kInvalid;
}

void expectSameFrames(const Map& a, const Map& b) {
  ASSERT_EQ(a.size(), b.size());
  EXPECT_EQ(a.names, b.names);
  EXPECT_EQ(a.config, b.config);
  ASSERT_EQ(a.poses.size(), b.poses.size());
  for (size_t f = 0; f < a.poses.size(); ++f) EXPECT_EQ(a.poses[f], b.poses[f]);
  ASSERT_EQ(a.database.globalDimension(), b.database.globalDimension());
  for (int f = 0; f < a.size(); ++f) {
    const auto& na = a.database.nodes(f);
    const auto& nb = b.database.nodes(f);
    ASSERT_EQ(na.size(), nb.size());
    for (size_t k = 0; k < na.size(); ++k) {
      EXPECT_EQ(na[k].centre, nb[k].centre);
      EXPECT_EQ(na[k].label, nb[k].label);
    }
    EXPECT_EQ(std::memcmp(a.database.global(f), b.database.global(f), sizeof(float) * a.database.globalDimension()), 0);
  }
}

void expectSameResult(const FrameResult& a, const FrameResult& b) {
  EXPECT_EQ(a.frame, b.frame);
  EXPECT_EQ(a.best, b.best);
  EXPECT_EQ(a.is_loop, b.is_loop);
  ASSERT_EQ(a.candidates.size(), b.candidates.size());
  for (size_t c = 0; c < a.candidates.size(); ++c) {
    EXPECT_EQ(a.candidates[c].frame, b.candidates[c].frame);
    EXPECT_EQ(a.candidates[c].distance2, b.candidates[c].distance2);
    EXPECT_EQ(a.candidates[c].match.score, b.candidates[c].match.score);
    EXPECT_EQ(a.candidates[c].match.T_match_query, b.candidates[c].match.T_match_query);
  }
}

TEST(MapFormat, RoundTripIsExactAndReencodesToTheSameBytes) {
  const test::NodeSequence s = test::circleSequence(40);
  const Config config = mapTestConfig();
  for (bool poses : {true, false}) {
    const Map original = mapOf(s, config, poses);
    const std::string bytes = map::encodeMap(original);
    map::MapLayout layout;
    const Map loaded = map::decodeMap(bytes, "m.sgtmap", RetrievalMethod::kBruteForce, &layout);
    expectSameFrames(original, loaded);
    EXPECT_EQ(loaded.hasPoses(), poses);
    EXPECT_EQ(map::encodeMap(loaded), bytes);
    EXPECT_EQ(layout.format_version, map::kFormatVersion);
    EXPECT_EQ(layout.file_bytes, bytes.size());
    EXPECT_EQ(layout.fingerprint, map::fingerprint(map::mapConfig(config)));
    ASSERT_EQ(layout.sections.size(), poses ? 5u : 4u);
    uint64_t total = 40;
    for (const auto& section : layout.sections) total += section.bytes;
    EXPECT_EQ(total, bytes.size());
    EXPECT_NO_THROW(map::checkCompatible(loaded, config, "m.sgtmap"));
  }
}

TEST(MapFormat, AnEmptyMapRoundTrips) {
  const Map empty = map::makeMap(FrameDatabase{}, mapTestConfig(), {});
  const Map loaded = map::decodeMap(map::encodeMap(empty), "empty.sgtmap");
  EXPECT_EQ(loaded.size(), 0);
  EXPECT_FALSE(loaded.hasPoses());
}

TEST(MapFormat, ResumingFromASavedMapEqualsOneRun) {
  const test::NodeSequence s = test::circleSequence(130);
  const Config config = mapTestConfig();
  std::vector<FrameResult> one_run;
  test::runNodes(s, config, &one_run);
  const int k = 70;
  test::NodeSequence head = s;
  head.frames.resize(k);
  head.names.resize(k);
  head.poses.resize(k);
  Map saved = map::decodeMap(map::encodeMap(mapOf(head, config)), "head.sgtmap");
  LoopDetector resumed(config, std::move(saved.database));
  int loops = 0;
  for (int f = k; f < 130; ++f) {
    const FrameResult r = resumed.process(s.frames[static_cast<size_t>(f)]);
    expectSameResult(r, one_run[static_cast<size_t>(f)]);
    loops += r.is_loop;
  }
  EXPECT_GE(loops, 25);  // frames 100..129 revisit 0..29
}

TEST(MapFormat, AResumedDetectorRefusesKeysOfAnotherLength) {
  Config other = mapTestConfig();
  other.retrieval.histogram_bins = 12;
  const LoopDetector d = test::runNodes(test::circleSequence(3), mapTestConfig());
  Map m = map::makeMap(d.database(), mapTestConfig(), test::circleSequence(3).names);
  EXPECT_THROW(LoopDetector(other, std::move(m.database)), Error);
}

/// A second session in the same world: 3 m beside the first route, started elsewhere, with other noise.
TEST(Relocalizer, ALoadedMapAnswersAsTheInMemoryOneAtAnyThreadCount) {
  const test::NodeSequence first = test::circleSequence(100);
  const test::NodeSequence second = test::circleSequence(30, 3.0, 0.9, /*seed=*/99);
  const Config config = mapTestConfig();
  const Map in_memory = mapOf(first, config);
  const std::string bytes = map::encodeMap(in_memory);
  const map::Relocalizer a(mapOf(first, config), config);
  const map::Relocalizer b(map::decodeMap(bytes, "m.sgtmap"), mapTestConfig(3));
  int localized = 0;
  for (const auto& nodes : second.frames) {
    const map::Relocalization ra = a.localize(nodes);
    const map::Relocalization rb = b.localize(nodes);
    expectSameResult(ra.search, rb.search);
    EXPECT_EQ(ra.map_frame, rb.map_frame);
    EXPECT_EQ(ra.T_mapframe_query, rb.T_mapframe_query);
    if (!ra.localized) continue;
    ++localized;
    ASSERT_TRUE(ra.T_world_query.has_value());
    EXPECT_EQ(*ra.T_world_query, *rb.T_world_query);
    EXPECT_EQ(ra.search.frame, -1);
    // No recent-frame exclusion: every map frame is eligible, and the pose lands on the query's true pose.
    const size_t q = static_cast<size_t>(&nodes - second.frames.data());
    const Eigen::Vector3d error = ra.T_world_query->topRightCorner<3, 1>() - second.poses[q].topRightCorner<3, 1>();
    EXPECT_LT(error.norm(), 0.3) << "query " << q << " at map frame " << ra.map_frame;
  }
  EXPECT_GE(localized, 27);
  EXPECT_EQ(a.map().size(), 100);  // nothing inserted
}

/// Real scans: a map of KITTI 00 frames 52, 88 and 850 (saved and loaded), queried with scan 4501, the revisit
/// of 52 2.96 m away: found among all three without any exclusion, with the ICP-refined reference pose.
TEST(Relocalizer, PlacesARealScanInAMapOfRealScans) {
  const Config config;
  LoopDetector detector(config);
  for (const char* frame : {"000052", "000088", "000850"}) detector.process(test::kittiScan(frame));
  Eigen::Matrix4d T_world_52 = test::rigid(30.0, 0.0, 0.0, Eigen::Vector3d(100.0, -5.0, 1.0));
  const std::vector<Eigen::Matrix4d> poses = {T_world_52, Eigen::Matrix4d::Identity(), Eigen::Matrix4d::Identity()};
  const Map saved = map::makeMap(detector.database(), config, {"000052", "000088", "000850"}, poses);
  const map::Relocalizer relocalizer(map::decodeMap(map::encodeMap(saved), "kitti.sgtmap"), config);
  const LabeledCloud query = test::kittiScan("004501");
  const map::Relocalization r = relocalizer.localize(query);
  ASSERT_TRUE(r.localized);
  EXPECT_EQ(r.map_frame, 0);
  EXPECT_EQ(r.search.extraction.input_points, query.points.size());
  const auto err = test::poseError(r.T_mapframe_query, test::referencePose4501To52());
  EXPECT_LT(err.translation_m, 0.15);
  EXPECT_LT(err.rotation_deg, 1.0);
  ASSERT_TRUE(r.T_world_query.has_value());
  EXPECT_TRUE(r.T_world_query->isApprox(T_world_52 * r.T_mapframe_query, 1e-12));
  // The points path is the node path after extraction.
  const map::Relocalization from_nodes = relocalizer.localize(NodeExtractor(config.cluster, config.labels,
                                                                            config.graph.max_nodes).extract(query).nodes);
  EXPECT_EQ(from_nodes.T_mapframe_query, r.T_mapframe_query);
  EXPECT_EQ(from_nodes.score, r.score);
}

TEST(Relocalizer, RefusesAMapOfAnotherConfiguration) {
  Config other = mapTestConfig();
  other.retrieval.histogram_bins = 12;
  try {
    map::Relocalizer(mapOf(test::circleSequence(5), mapTestConfig()), other, "m.sgtmap");
    FAIL();
  } catch (const MapError& e) {
    EXPECT_EQ(e.problem(), MapProblem::kIncompatible);
    EXPECT_NE(std::string(e.what()).find("m.sgtmap: "), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("retrieval.histogram_bins: the map was built with 30, the configuration has 12"),
              std::string::npos)
        << e.what();
  }
  // Query-time settings are free to change.
  Config query_time = mapTestConfig(4);
  query_time.verification.sigma_4 = 0.5;
  query_time.retrieval.num_candidates = 3;
  query_time.retrieval.method = RetrievalMethod::kKdTree;
  EXPECT_NO_THROW(map::Relocalizer(mapOf(test::circleSequence(5), mapTestConfig()), query_time));
}

TEST(MapFormat, EveryFlippedByteFailsCleanly) {
  const std::string bytes = map::encodeMap(mapOf(test::circleSequence(3), mapTestConfig()));
  ASSERT_LT(bytes.size(), 20000u);
  for (size_t i = 0; i < bytes.size(); ++i) {
    std::string damaged = bytes;
    damaged[i] = static_cast<char>(damaged[i] ^ 0xFF);
    std::string message;
    const MapProblem p = problemOf(damaged, &message);
    EXPECT_EQ(p, i < 8 ? MapProblem::kNotAMap : MapProblem::kCorrupted) << "byte " << i << ": " << message;
    EXPECT_EQ(message.rfind("m.sgtmap: ", 0), 0u) << message;
    if (i >= 8) {
      EXPECT_NE(message.find("corrupted map"), std::string::npos) << message;
    }
  }
}

TEST(MapFormat, EveryTruncationFailsCleanly) {
  const std::string bytes = map::encodeMap(mapOf(test::circleSequence(3), mapTestConfig()));
  for (size_t n = 0; n < bytes.size(); ++n) {
    std::string message;
    EXPECT_EQ(problemOf(std::string_view(bytes).substr(0, n), &message), MapProblem::kTruncated) << n << ": " << message;
    EXPECT_NE(message.find("m.sgtmap: truncated map file"), std::string::npos) << message;
  }
  EXPECT_EQ(problemOf(bytes + "x"), MapProblem::kCorrupted);
  EXPECT_EQ(problemOf("P3\n# not a map at all"), MapProblem::kNotAMap);
}

void setWord(std::string& bytes, size_t at, uint32_t value) { std::memcpy(&bytes[at], &value, 4); }
uint32_t crcOf(std::string_view b) {
  return static_cast<uint32_t>(crc32_z(0, reinterpret_cast<const Bytef*>(b.data()), b.size()));
}

TEST(MapFormat, NewerVersionsAreNamedAndUnknownSectionsSkipped) {
  const std::string bytes = map::encodeMap(mapOf(test::circleSequence(3), mapTestConfig()));
  std::string newer = bytes;
  setWord(newer, 8, map::kFormatVersion + 1);
  setWord(newer, 36, crcOf(std::string_view(newer).substr(0, 36)));
  std::string message;
  EXPECT_EQ(problemOf(newer, &message), MapProblem::kNewerVersion);
  const std::string v = std::to_string(map::kFormatVersion);
  EXPECT_NE(message.find("map format version " + std::to_string(map::kFormatVersion + 1) + " is newer than this sgtllc reads (" + v + ")"),
            std::string::npos)
      << message;

  // The first section (CONF) at version 2: its checksum covers its head.
  std::string newer_section = bytes;
  uint64_t payload;
  std::memcpy(&payload, &bytes[48], 8);
  setWord(newer_section, 44, 2);
  setWord(newer_section, 56 + payload, crcOf(std::string_view(newer_section).substr(40, 16 + payload)));
  EXPECT_EQ(problemOf(newer_section, &message), MapProblem::kNewerVersion);
  EXPECT_NE(message.find("section CONF has version 2"), std::string::npos) << message;

  // A section a later writer may add (an index readers can rebuild) is skipped.
  std::string extra = "XIDX";
  const uint32_t one = 1;
  const uint64_t three = 3;
  extra.append(reinterpret_cast<const char*>(&one), 4).append(reinterpret_cast<const char*>(&three), 8).append("abc");
  const uint32_t extra_crc = crcOf(extra);
  extra.append(reinterpret_cast<const char*>(&extra_crc), 4);
  std::string longer = bytes + extra;
  setWord(longer, 12, 6);
  const uint64_t size = longer.size();
  std::memcpy(&longer[16], &size, 8);
  setWord(longer, 36, crcOf(std::string_view(longer).substr(0, 36)));
  map::MapLayout layout;
  const Map m = map::decodeMap(longer, "m.sgtmap", RetrievalMethod::kBruteForce, &layout);
  // The same section twice is damage, not an extension.
  std::string twice = longer + extra;
  setWord(twice, 12, 7);
  const uint64_t twice_size = twice.size();
  std::memcpy(&twice[16], &twice_size, 8);
  setWord(twice, 36, crcOf(std::string_view(twice).substr(0, 36)));
  EXPECT_EQ(problemOf(twice, &message), MapProblem::kCorrupted);
  EXPECT_NE(message.find("a second XIDX section"), std::string::npos) << message;
  EXPECT_EQ(m.size(), 3);
  ASSERT_EQ(layout.sections.size(), 6u);
  EXPECT_EQ(layout.sections.back().tag, "XIDX");
  EXPECT_FALSE(layout.sections.back().known);
}

TEST(MapFormat, MapsWithBadFramesAreNotWritten) {
  const test::NodeSequence s = test::circleSequence(3);
  const LoopDetector d = test::runNodes(s, mapTestConfig());
  std::vector<std::string> names = s.names;
  names[2] = names[0];
  try {
    map::makeMap(d.database(), mapTestConfig(), names);
    FAIL();
  } catch (const MapError& e) {
    EXPECT_EQ(e.problem(), MapProblem::kInvalid);
    EXPECT_NE(std::string(e.what()).find("frame name '000000' is used twice"), std::string::npos) << e.what();
  }
  EXPECT_THROW(map::makeMap(d.database(), mapTestConfig(), {"a", "b"}), MapError);
  EXPECT_THROW(map::makeMap(d.database(), mapTestConfig(), s.names, {s.poses[0]}), MapError);
  EXPECT_THROW(map::makeMap(d.database(), mapTestConfig(), {"a", "", "c"}), MapError);
}

}  // namespace
}  // namespace sgtllc
