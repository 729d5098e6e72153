// A new session joining a saved map (docs/sessions.md): sessions of the synthetic circular world of
// test_map_support.h given as node frames, the second one 2 m aside, another way round the start and with odometry
// in a frame of its own; the merged map and its session section through the map format.
#include <gtest/gtest.h>

#include <algorithm>

#include "sgtllc/map/map_format.h"
#include "sgtllc/map/thinning.h"
#include "sgtllc/pipeline/session_pipeline.h"
#include "test_map_support.h"

namespace sgtllc {
namespace {

Config sessionConfig(double keep_distance_m = 0.0) {
  Config c;
  c.retrieval.exclude_recent = 20;
  c.backend.sessions.keep_distance_m = keep_distance_m;  // 0: every frame joins the map (thinning tested apart)
  return c;
}

map::Map firstMap(const Config& config) {
  const test::NodeSequence s = test::circleSequence(110);
  const LoopDetector detector = test::runNodes(s, config);
  return map::makeMap(detector.database(), config, s.names, s.poses);
}

/// Feeds @p s to @p pipeline with odometry in its own frame (T_first⁻¹ · T_i: the identity at its first frame).
void feed(pipeline::SessionPipeline& pipeline, const test::NodeSequence& s) {
  const Eigen::Isometry3d first_inv(s.poses.front().inverse());
  for (size_t i = 0; i < s.frames.size(); ++i) {
    pipeline::LoadedFrame frame;
    frame.nodes = s.frames[i];
    pipeline.addFrame(std::move(frame), first_inv * Eigen::Isometry3d(s.poses[i]), s.names[i]);
  }
}

double worstError(const std::vector<Eigen::Isometry3d>& poses, const test::NodeSequence& truth) {
  double worst = 0.0;
  for (size_t i = 0; i < poses.size(); ++i) {
    worst = std::max(worst, (poses[i].translation() - truth.poses[i].topRightCorner<3, 1>()).norm());
  }
  return worst;
}

TEST(SessionPipeline, PlacesASessionInTheMapsFrameAndMergesIt) {
  const Config config = sessionConfig();
  const test::NodeSequence second = test::circleSequence(40, 2.0, 0.9, /*seed=*/99);
  pipeline::SessionPipeline session(firstMap(config), config, {"s2", "first"});
  feed(session, second);
  EXPECT_EQ(session.mapFrames(), 110);
  // Before the merge the poses are the odometry, in the session's own frame: metres from the truth.
  EXPECT_GT(worstError(session.poses(), second), 10.0);
  const pipeline::SessionClosing& closing = session.finish();
  ASSERT_TRUE(closing.merge.placed);
  EXPECT_GE(closing.merge.inter_accepted, 30);
  EXPECT_EQ(closing.merge.inter_loops + 0, static_cast<int>(session.loops().size()));  // 40 frames: no own revisit
  EXPECT_LT(worstError(session.poses(), second), 0.1);
  for (const pipeline::ClosingLoop& l : session.loops()) {
    EXPECT_EQ(l.query.rfind("s2/", 0), 0u) << l.query;
    EXPECT_LT(l.edge.from, 110);
    EXPECT_GE(l.edge.to, 110);
  }

  const map::Map merged = session.mergedMap();
  ASSERT_EQ(merged.size(), 150);
  ASSERT_EQ(merged.sessions.size(), 2u);
  EXPECT_EQ(merged.sessions[0].name, "first");
  EXPECT_EQ(merged.sessions[0].frames, 110);
  EXPECT_EQ(merged.sessions[1].name, "s2");
  EXPECT_EQ(merged.sessions[1].first, 110);
  EXPECT_EQ(merged.names[110], "s2/000000");
  EXPECT_LT((merged.poses[149].topRightCorner<3, 1>() - second.poses[39].topRightCorner<3, 1>()).norm(), 0.1);

  // Through the file: the sessions come back, and a third session joins the merged map in turn.
  const std::string bytes = map::encodeMap(merged);
  map::MapLayout layout;
  const map::Map loaded = map::decodeMap(bytes, "m.sgtmap", RetrievalMethod::kBruteForce, &layout);
  ASSERT_EQ(loaded.sessions.size(), 2u);
  EXPECT_EQ(loaded.sessions[1].name, "s2");
  EXPECT_EQ(loaded.sessions[1].frames, 40);
  EXPECT_EQ(layout.sections.back().tag, "SESS");
  EXPECT_EQ(map::encodeMap(loaded), bytes);
  const test::NodeSequence third = test::circleSequence(30, -2.0, 2.5, /*seed=*/7);
  pipeline::SessionPipeline next(map::decodeMap(bytes, "m.sgtmap"), config, {"s3", "unused"});
  feed(next, third);
  ASSERT_TRUE(next.finish().merge.placed);
  EXPECT_LT(worstError(next.poses(), third), 0.1);
  const map::Map three = next.mergedMap();
  ASSERT_EQ(three.sessions.size(), 3u);
  EXPECT_EQ(three.sessions[2].first, 150);
  EXPECT_EQ(three.names.back(), "s3/000029");
}

TEST(SessionPipeline, FramesTheMapHasAndRecognisesDoNotJoinIt) {
  // The first session's circle driven again 0.3 m aside: every frame within 2 m of a map frame facing its way.
  const test::NodeSequence again = test::circleSequence(60, 0.3, 0.02, /*seed=*/5);
  const Config thin = sessionConfig(2.0);
  pipeline::SessionPipeline session(firstMap(thin), thin, {"again"});
  feed(session, again);
  ASSERT_TRUE(session.finish().merge.placed);
  const std::vector<bool> kept = session.framesKept();
  int added = 0, recognised = 0;
  for (bool k : kept) added += k;
  for (const pipeline::ClosingLoop& l : session.loops()) recognised += l.edge.from < 110;
  EXPECT_EQ(recognised, session.closing()->merge.inter_loops);  // every loop of this drive goes to the map
  EXPECT_EQ(added, 60 - session.closing()->merge.inter_accepted);  // the unrecognised frames only
  EXPECT_LE(added, 6);
  const map::Map merged = session.mergedMap();
  EXPECT_EQ(merged.size(), 110 + added);
  EXPECT_EQ(merged.sessions.back().frames, added);
  for (int f = 110; f < merged.size(); ++f) EXPECT_EQ(merged.names[f].rfind("again/", 0), 0u);
  // Each frame's drive, as the thinning rule counts them: the first map's frames are drive 0, the merged ones 1.
  ASSERT_EQ(merged.sessions.size(), 2u);
  const std::vector<int> drive = map::frameSessions(merged);
  ASSERT_EQ(static_cast<int>(drive.size()), merged.size());
  for (int f = 0; f < merged.size(); ++f) EXPECT_EQ(drive[f], f < 110 ? 0 : 1) << f;
  EXPECT_EQ(map::frameSessions(firstMap(thin)), std::vector<int>(110, 0));  // no sessions listed: one drive
  // The same drive turned round: the map's frames face the other way, so every frame joins.
  const std::vector<Eigen::Matrix4d> map_poses = firstMap(thin).poses;
  const auto added_by = [&](bool turned, bool known, double distance) {
    std::vector<Eigen::Isometry3d> poses;
    for (const Eigen::Matrix4d& T : again.poses) {
      poses.emplace_back(T);
      if (turned) poses.back().rotate(Eigen::AngleAxisd(M_PI, Eigen::Vector3d::UnitZ()));
    }
    const std::vector<bool> keep =
        map::framesThatAdd(map_poses, {}, poses, std::vector<bool>(60, known), {distance, 45.0, 2});
    return std::count(keep.begin(), keep.end(), true);
  };
  EXPECT_EQ(added_by(false, true, 2.0), 0);   // facing the map's way, recognised: none
  EXPECT_EQ(added_by(true, true, 2.0), 60);   // turned round: the map's frames face the other way
  EXPECT_EQ(added_by(false, false, 2.0), 60); // not recognised, covered by one drive: all
  EXPECT_EQ(added_by(false, true, 0.0), 60);  // no distance: all
}

TEST(SessionPipeline, AnUnrecognisedPlaceGainsOneMoreDrivesViewNotOnePerDrive) {
  // A map of two drives along the x axis, one frame a metre, both facing +x: drive 0 at x = 0..9, drive 1 at
  // x = 5..14 (so x = 5..9 is covered by both). A third drive's frames at x = 0.4..14.4, none recognised.
  std::vector<Eigen::Matrix4d> map_poses;
  std::vector<int> drive;
  for (int x = 0; x < 10; ++x) {
    map_poses.push_back(Eigen::Matrix4d::Identity());
    map_poses.back()(0, 3) = x;
    drive.push_back(0);
  }
  for (int x = 5; x < 15; ++x) {
    map_poses.push_back(Eigen::Matrix4d::Identity());
    map_poses.back()(0, 3) = x;
    drive.push_back(1);
  }
  std::vector<Eigen::Isometry3d> frames;
  for (int x = 0; x < 15; ++x) frames.push_back(Eigen::Isometry3d(Eigen::Translation3d(x + 0.4, 0.0, 0.0)));
  const std::vector<bool> missed(frames.size(), false);
  const auto kept = [&](int max_sessions) {
    const std::vector<bool> keep = map::framesThatAdd(map_poses, drive, frames, missed, {0.7, 45.0, max_sessions});
    std::vector<int> xs;
    for (size_t f = 0; f < keep.size(); ++f) {
      if (keep[f]) xs.push_back(static_cast<int>(f));
    }
    return xs;
  };
  // Within 0.7 m of frame f (at f + 0.4) lie the map frames at f and f + 1: for f = 4..9 they come from both drives.
  EXPECT_EQ(kept(2), (std::vector<int>{0, 1, 2, 3, 10, 11, 12, 13, 14}));
  EXPECT_EQ(kept(1), std::vector<int>{});  // 1: no unrecognised covered frame joins
  EXPECT_EQ(kept(3).size(), frames.size());  // never three drives here: every frame joins, as with no cap
  EXPECT_EQ(kept(3), kept(1000));
  // Facing the other way, nothing covers them: all join, whatever the cap.
  for (Eigen::Isometry3d& T : frames) T.rotate(Eigen::AngleAxisd(M_PI, Eigen::Vector3d::UnitZ()));
  EXPECT_EQ(kept(1).size(), frames.size());
  // At x = 6.4, covered by both drives: recognised or missed, it does not join; as a map that lists no drives (one
  // drive), the missed one joins.
  const std::vector<Eigen::Isometry3d> both(2, Eigen::Isometry3d(Eigen::Translation3d(6.4, 0.0, 0.0)));
  const map::ThinningRule rule{0.7, 45.0, 2};
  EXPECT_EQ(map::framesThatAdd(map_poses, drive, both, {true, false}, rule), (std::vector<bool>{false, false}));
  EXPECT_EQ(map::framesThatAdd(map_poses, {}, both, {true, false}, rule), (std::vector<bool>{false, true}));
}

TEST(SessionPipeline, ASessionWithoutInterSessionLoopsIsNotMerged) {
  const Config config = sessionConfig();
  // Another world: the map's places with their classes changed, so no frame matches the map.
  test::NodeSequence elsewhere = test::circleSequence(30, 0.0, 0.0, 3);
  for (auto& frame : elsewhere.frames) {
    for (Node& n : frame) n.label = (n.label + 1) % kNumPaperClasses;  // other classes at the map's places
  }
  pipeline::SessionPipeline session(firstMap(config), config, {"away"});
  feed(session, elsewhere);
  const pipeline::SessionClosing& closing = session.finish();
  EXPECT_FALSE(closing.merge.placed);
  EXPECT_LT(closing.merge.inter_accepted, 1);
  EXPECT_THROW(session.mergedMap(), Error);
  EXPECT_THROW(session.finish(), Error);
}

TEST(SessionPipeline, LoopsFromElsewherePlaceASessionTheDetectorCannot) {
  // The session of the test above, whose classes match nothing in the map, with three inter-session loops from
  // another source (as a surveyor's tie would give): its frames 5, 15, 25 stand where the map's do.
  const Config config = sessionConfig();
  test::NodeSequence elsewhere = test::circleSequence(30, 0.0, 0.0, 3);
  for (auto& frame : elsewhere.frames) {
    for (Node& n : frame) n.label = (n.label + 1) % kNumPaperClasses;
  }
  pipeline::SessionPipeline session(firstMap(config), config, {"away"});
  feed(session, elsewhere);
  for (const int k : {5, 15, 25}) {
    pipeline::ClosingLoop l;
    l.edge = {k, 110 + k, Eigen::Isometry3d::Identity(), pipeline::nominalLoopInformation(config.backend.loops),
              backend::EdgeKind::kLoop};
    session.addLoop(l);
  }
  pipeline::ClosingLoop bad;
  bad.edge.from = 3, bad.edge.to = 4;
  EXPECT_THROW(session.addLoop(bad), Error);  // two map frames
  bad.edge.from = 115, bad.edge.to = 3;
  EXPECT_THROW(session.addLoop(bad), Error);  // from the session to the map: the other way round
  bad.edge.from = 3, bad.edge.to = 110 + 30;
  EXPECT_THROW(session.addLoop(bad), Error);  // a session frame not added yet
  const pipeline::SessionClosing& closing = session.finish();
  ASSERT_TRUE(closing.merge.placed);
  EXPECT_EQ(closing.merge.inter_accepted, 3);
  EXPECT_LT(worstError(session.poses(), elsewhere), 0.01);
  bad.edge.from = 3, bad.edge.to = 115;
  EXPECT_THROW(session.addLoop(bad), Error);  // after finish()
}

TEST(SessionPipeline, RefusesBadNamesAMapWithoutPosesAndFramesAfterTheEnd) {
  const Config config = sessionConfig();
  for (const char* name : {"", "a/b"}) {
    EXPECT_THROW(pipeline::SessionPipeline(firstMap(config), config, {name}), Error) << name;
  }
  EXPECT_THROW(pipeline::SessionPipeline(firstMap(config), config, {"map", "map"}), Error);  // taken
  map::Map no_poses = firstMap(config);
  no_poses.poses.clear();
  EXPECT_THROW(pipeline::SessionPipeline(std::move(no_poses), config, {"s"}), Error);
  pipeline::SessionPipeline session(firstMap(config), config, {"s"});
  EXPECT_THROW(session.finish(), Error);  // no frames
  feed(session, test::circleSequence(3));
  session.finish();
  EXPECT_THROW(session.addFrame({}, Eigen::Isometry3d::Identity()), Error);
}

TEST(MapSessions, MustCoverTheFramesInOrderWithUniqueNames) {
  const Config config = sessionConfig();
  map::Map m = firstMap(config);
  EXPECT_NO_THROW(map::encodeMap(m));  // none: one unnamed drive
  const std::vector<std::vector<map::MapSession>> bad = {
      {{"a", 0, 100}},                    // frames 100..109 in none
      {{"a", 0, 60}, {"b", 50, 60}},      // overlap
      {{"a", 0, 60}, {"b", 61, 49}},      // gap
      {{"a", 0, 60}, {"a", 60, 50}},      // a name twice
      {{"a/b", 0, 110}},                  // a '/'
      {{"", 0, 110}},                     // empty
      {{"a", 0, -1}, {"b", 0, 110}},      // a negative count
      {{"a", 0, 111}},                    // beyond the frames
  };
  for (const auto& sessions : bad) {
    m.sessions = sessions;
    try {
      map::encodeMap(m);
      ADD_FAILURE() << sessions.front().name;
    } catch (const map::MapError& e) {
      EXPECT_EQ(e.problem(), map::MapProblem::kInvalid) << e.what();
    }
  }
  m.sessions = {{"a", 0, 60}, {"b", 60, 50}};
  EXPECT_EQ(map::decodeMap(map::encodeMap(m), "m").sessions.size(), 2u);
  m.sessions = {{"a", 0, 110}, {"b", 110, 0}};  // a drive the map covered already adds no frame
  EXPECT_EQ(map::decodeMap(map::encodeMap(m), "m").sessions[1].frames, 0);
}

}  // namespace
}  // namespace sgtllc
