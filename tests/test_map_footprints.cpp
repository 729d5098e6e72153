// Footprints in map files (docs/map-format.md, FTPR): kept exactly through a file, used by the relocalizer and by
// a resumed detector (the footprint check of algorithm §7.7 with a loaded map), refused when malformed. Real
// KITTI 00 scans.
#include <gtest/gtest.h>

#include <zlib.h>

#include <cstring>

#include "sgtllc/map/map_format.h"
#include "sgtllc/map/relocalizer.h"
#include "test_kitti_support.h"

namespace sgtllc {
namespace {

using map::Map;
using map::MapError;
using map::MapProblem;

/// A detector over KITTI 00 frames 52, 88 and 850 (scans, with footprints) and one frame given as nodes (none).
class MapFootprints : public ::testing::Test {
 protected:
  void SetUp() override {
    config_.retrieval.exclude_recent = 1;
    detector_ = std::make_unique<LoopDetector>(config_);
    for (const char* frame : {"000052", "000088", "000850"}) detector_->process(test::kittiScan(frame));
    nodes_only_ = NodeExtractor(config_.cluster, config_.labels).extract(test::kittiScan("000088")).nodes;
    for (Node& n : nodes_only_) n.centre.x() += 500.0;  // another place
    detector_->process(nodes_only_);
  }
  Map saved() const {
    return map::makeMap(detector_->database(), config_, {"000052", "000088", "000850", "nodes"}, {},
                        detector_->footprints());
  }
  Config config_;
  std::unique_ptr<LoopDetector> detector_;
  std::vector<Node> nodes_only_;
};

TEST_F(MapFootprints, RoundTripKeepsEveryBitAndTheFrameWithout) {
  const Map m = saved();
  ASSERT_EQ(m.footprints.size(), 4u);
  EXPECT_TRUE(m.footprints[3].empty());
  const std::string bytes = map::encodeMap(m);
  map::MapLayout layout;
  const Map loaded = map::decodeMap(bytes, "m.sgtmap", RetrievalMethod::kBruteForce, &layout);
  EXPECT_EQ(layout.sections.back().tag, "FTPR");
  EXPECT_TRUE(layout.sections.back().known);
  ASSERT_EQ(loaded.footprints.size(), 4u);
  for (size_t f = 0; f < 4; ++f) {
    EXPECT_EQ(loaded.footprints[f].bits, detector_->footprints()[f].bits) << f;
    EXPECT_EQ(loaded.footprints[f].half, detector_->footprints()[f].half) << f;
    EXPECT_EQ(loaded.footprints[f].cell, detector_->footprints()[f].cell) << f;
  }
  EXPECT_EQ(loaded.footprints[0].half, 80);  // 40 m / 0.5 m
  EXPECT_EQ(map::encodeMap(loaded), bytes);
  // 3 grids of 160 × 160 bits (3,200 bytes) and 8 bytes of cell and size per frame, in a section of 20 bytes more.
  EXPECT_EQ(layout.sections.back().bytes, 16u + 8u + 4 * 8u + 3 * 3200u + 4u);
  // Without footprints (nodes only, or the check off) no section is written.
  const Map bare = map::makeMap(detector_->database(), config_, {"a", "b", "c", "d"});
  EXPECT_TRUE(bare.footprints.empty());
  map::MapLayout bare_layout;
  map::decodeMap(map::encodeMap(bare), "m.sgtmap", RetrievalMethod::kBruteForce, &bare_layout);
  for (const map::SectionInfo& s : bare_layout.sections) EXPECT_NE(s.tag, "FTPR");
}

TEST_F(MapFootprints, TheRelocalizerChecksTheFootprintOfAMapFrame) {
  const LabeledCloud query = test::kittiScan("004501");
  const map::Relocalizer with(map::decodeMap(map::encodeMap(saved()), "m.sgtmap"), config_);
  const map::Relocalization r = with.localize(query);
  ASSERT_TRUE(r.localized);
  ASSERT_EQ(r.map_frame, 0);
  const Candidate& found = r.search.candidates[static_cast<size_t>(r.search.best)];
  EXPECT_GT(found.match.footprint.compared, 200);
  EXPECT_GT(found.match.footprint.share, 0.9);
  // A map without them answers alike, unchecked.
  const map::Relocalizer without(map::makeMap(detector_->database(), config_, {"a", "b", "c", "d"}), config_);
  const map::Relocalization bare = without.localize(query);
  ASSERT_TRUE(bare.localized);
  EXPECT_EQ(bare.search.candidates[static_cast<size_t>(bare.search.best)].match.footprint.compared, 0);
  EXPECT_EQ(bare.T_mapframe_query, r.T_mapframe_query);
  // Frame 52's nodes with the footprint of frame 850, 300 m away: its structure contradicts the pose.
  Map contradicted = saved();
  contradicted.footprints[0] = contradicted.footprints[2];
  const map::Relocalizer lying(std::move(contradicted), config_);
  const map::Relocalization no = lying.localize(query);
  EXPECT_FALSE(no.localized);
  for (const Candidate& c : no.search.candidates) {
    if (c.frame == 0) {
      EXPECT_EQ(c.match.rejection, Rejection::kFootprint);
    }
  }
}

TEST_F(MapFootprints, AResumedDetectorChecksAsTheOneThatSavedTheMap) {
  Map loaded = map::decodeMap(map::encodeMap(saved()), "m.sgtmap");
  Map again = map::decodeMap(map::encodeMap(saved()), "m.sgtmap");
  LoopDetector resumed(config_, std::move(loaded.database), loaded.footprints);
  const LabeledCloud query = test::kittiScan("004501");
  const FrameResult a = resumed.process(query);
  const FrameResult b = detector_->process(query);
  ASSERT_TRUE(a.is_loop);
  ASSERT_EQ(a.candidates.size(), b.candidates.size());
  for (size_t c = 0; c < a.candidates.size(); ++c) {
    EXPECT_EQ(a.candidates[c].match.footprint.compared, b.candidates[c].match.footprint.compared) << c;
    EXPECT_EQ(a.candidates[c].match.footprint.share, b.candidates[c].match.footprint.share) << c;
    EXPECT_EQ(a.candidates[c].match.score, b.candidates[c].match.score) << c;
  }
  EXPECT_EQ(resumed.footprints().size(), 5u);
  EXPECT_THROW(LoopDetector(config_, std::move(again.database), std::vector<Footprint>(2)), Error);
}

TEST_F(MapFootprints, MalformedFootprintsAreNotWrittenNorRead) {
  Map two = saved();
  two.footprints.pop_back();
  EXPECT_EQ([&] {
    try {
      map::encodeMap(two, "out.sgtmap");
    } catch (const MapError& e) {
      return e.problem();
    }
    return MapProblem::kNotAMap;
  }(), MapProblem::kInvalid);
  Map dilated = saved();
  dilated.footprints[1] = dilateFootprint(dilated.footprints[1]);
  EXPECT_THROW(map::encodeMap(dilated, "out.sgtmap"), MapError);

  // A grid size beyond the bound, with a checksum that fits: refused as corrupted, naming the problem.
  std::string bytes = map::encodeMap(saved());
  map::MapLayout layout;
  map::decodeMap(bytes, "m", RetrievalMethod::kBruteForce, &layout);
  const size_t start = bytes.size() - layout.sections.back().bytes;
  const size_t payload = layout.sections.back().bytes - 20;
  const int32_t huge = map::kMaxFootprintHalf + 1;
  std::memcpy(&bytes[start + 16 + 8 + 4], &huge, 4);  // frame 0's half
  const uint32_t crc = static_cast<uint32_t>(
      crc32(0, reinterpret_cast<const Bytef*>(bytes.data() + start), static_cast<uInt>(16 + payload)));
  std::memcpy(&bytes[start + 16 + payload], &crc, 4);
  try {
    map::decodeMap(bytes, "m.sgtmap");
    ADD_FAILURE() << "decoded";
  } catch (const MapError& e) {
    EXPECT_EQ(e.problem(), MapProblem::kCorrupted);
    EXPECT_NE(std::string(e.what()).find("a footprint grid of 4097 half-cells"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace sgtllc
