// Footprints and sights in map files (docs/map-format.md, FTPR and SGHT): kept exactly through a file, used by the relocalizer and by
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

/// Where section @p tag starts in an encoded map (its head), from the layout decodeMap reported.
size_t sectionStart(const map::MapLayout& layout, const std::string& tag) {
  size_t at = 40;  // the header
  for (const map::SectionInfo& s : layout.sections) {
    if (s.tag == tag) return at;
    at += s.bytes;
  }
  ADD_FAILURE() << "no section " << tag;
  return at;
}

const map::SectionInfo* sectionOf(const map::MapLayout& layout, const std::string& tag) {
  for (const map::SectionInfo& s : layout.sections) {
    if (s.tag == tag) return &s;
  }
  return nullptr;
}

/// Decodes @p bytes, expecting it refused as corrupted with @p message in the error.
void expectCorrupted(const std::string& bytes, const std::string& message) {
  try {
    map::decodeMap(bytes, "m.sgtmap");
    ADD_FAILURE() << "decoded";
  } catch (const MapError& e) {
    EXPECT_EQ(e.problem(), MapProblem::kCorrupted);
    EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
  }
}

/// Rewrites the crc of the section starting at @p start (payload @p payload bytes), so a change inside it passes
/// the checksum and reaches its parser.
void resealSection(std::string* bytes, size_t start, size_t payload) {
  const uint32_t crc = static_cast<uint32_t>(
      crc32(0, reinterpret_cast<const Bytef*>(bytes->data() + start), static_cast<uInt>(16 + payload)));
  std::memcpy(&(*bytes)[start + 16 + payload], &crc, 4);
}

/// A detector over KITTI 00 frames 52, 88 and 850 (scans, with footprints) and one frame given as nodes (none).
class MapFootprints : public ::testing::Test {
 protected:
  void SetUp() override {
    config_.retrieval.exclude_recent = 1;
    config_.verification.max_seen_through = 0.5;  // the frames keep sights only with the seen-through check on
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
  const map::SectionInfo* ftpr = sectionOf(layout, "FTPR");
  const map::SectionInfo* sght = sectionOf(layout, "SGHT");
  ASSERT_TRUE(ftpr && sght);
  EXPECT_TRUE(ftpr->known && sght->known);
  ASSERT_EQ(loaded.footprints.size(), 4u);
  for (size_t f = 0; f < 4; ++f) {
    EXPECT_EQ(loaded.footprints[f].bits, detector_->footprints()[f].bits) << f;
    EXPECT_EQ(loaded.footprints[f].half, detector_->footprints()[f].half) << f;
    EXPECT_EQ(loaded.footprints[f].cell, detector_->footprints()[f].cell) << f;
    EXPECT_EQ(loaded.footprints[f].sight.low, detector_->footprints()[f].sight.low) << f;
    EXPECT_EQ(loaded.footprints[f].sight.high, detector_->footprints()[f].sight.high) << f;
  }
  EXPECT_EQ(loaded.footprints[0].half, 80);  // 40 m / 0.5 m
  EXPECT_EQ(loaded.footprints[0].sight.high.size(), 360u);
  EXPECT_TRUE(loaded.footprints[3].sight.empty());
  EXPECT_EQ(map::encodeMap(loaded), bytes);
  // 3 grids of 160 × 160 bits (3,200 bytes) and 8 bytes of cell and size per frame, in a section of 20 bytes more;
  // 3 sights of 2 × 360 bytes and 2 bytes of sector count per frame, the same.
  EXPECT_EQ(ftpr->bytes, 16u + 8u + 4 * 8u + 3 * 3200u + 4u);
  EXPECT_EQ(sght->bytes, 16u + 8u + 4 * 2u + 3 * 720u + 4u);
  // Footprints without sights (as an earlier build saved them): no SGHT, and they load without.
  Map sightless = saved();
  for (Footprint& f : sightless.footprints) f.sight = Sight{};
  map::MapLayout sightless_layout;
  const Map reloaded =
      map::decodeMap(map::encodeMap(sightless), "m.sgtmap", RetrievalMethod::kBruteForce, &sightless_layout);
  EXPECT_EQ(sectionOf(sightless_layout, "SGHT"), nullptr);
  EXPECT_TRUE(reloaded.footprints[0].sight.empty());
  EXPECT_EQ(reloaded.footprints[0].bits, detector_->footprints()[0].bits);
  // Without footprints (nodes only, or the check off) no section is written.
  const Map bare = map::makeMap(detector_->database(), config_, {"a", "b", "c", "d"});
  EXPECT_TRUE(bare.footprints.empty());
  map::MapLayout bare_layout;
  map::decodeMap(map::encodeMap(bare), "m.sgtmap", RetrievalMethod::kBruteForce, &bare_layout);
  for (const map::SectionInfo& s : bare_layout.sections) {
    EXPECT_NE(s.tag, "FTPR");
    EXPECT_NE(s.tag, "SGHT");
  }
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
  const size_t start = sectionStart(layout, "FTPR");
  const int32_t huge = map::kMaxFootprintHalf + 1;
  std::memcpy(&bytes[start + 16 + 8 + 4], &huge, 4);  // frame 0's half
  resealSection(&bytes, start, sectionOf(layout, "FTPR")->bytes - 20);
  expectCorrupted(bytes, "a footprint grid of 4097 half-cells");

  // A sight of another sector count, likewise.
  std::string sights = map::encodeMap(saved());
  const size_t at = sectionStart(layout, "SGHT");
  const uint16_t sectors = 200;
  std::memcpy(&sights[at + 16 + 8], &sectors, 2);  // frame 0's sector count
  resealSection(&sights, at, sectionOf(layout, "SGHT")->bytes - 20);
  expectCorrupted(sights, "a sight of 200 sectors");
  // A sight of the wrong size in memory is not written.
  Map short_sight = saved();
  short_sight.footprints[0].sight.high.resize(100);
  EXPECT_THROW(map::encodeMap(short_sight, "out.sgtmap"), MapError);
  // Nor a half sight on a frame without a footprint grid (a node file's frame).
  Map half_sight = saved();
  half_sight.footprints[3].sight.high.assign(kSightSectors, 4);
  EXPECT_THROW(map::encodeMap(half_sight, "out.sgtmap"), MapError);
}

}  // namespace
}  // namespace sgtllc
