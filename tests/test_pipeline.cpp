// The loop-closing pipeline on the bundled KITTI 00 scans with their KISS-ICP odometry: it detects what the detector
// detects, turns the loop into the back end's edge, solves as the back end does (batch and online), accumulates
// scans as the accumulator merges them, and refuses input it cannot use without storing any of it.
#include <gtest/gtest.h>

#include "sgtllc/accumulate/scan_accumulator.h"
#include "sgtllc/backend/information.h"
#include "sgtllc/io/trajectory.h"
#include "sgtllc/pipeline/loop_closing_pipeline.h"
#include "test_kitti_support.h"

namespace sgtllc {
namespace {

using pipeline::LoopClosingPipeline;
using pipeline::PipelineFrame;
using pipeline::PipelineOptions;

const std::vector<std::string> kFrames = {"000052", "000088", "000850", "004501"};

class Pipeline : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    scans = new std::vector<LabeledCloud>;
    odometry = new std::vector<Eigen::Isometry3d>;
    const io::Trajectory kiss = io::readTrajectory(test::dataPath("kitti/00/kissicp_00_kitti.txt"),
                                                   test::dataPath("kitti/00/calib.txt"), io::PoseFrame::kCam0)
                                    .trajectory;
    for (const std::string& f : kFrames) {
      scans->push_back(test::kittiScan(f));
      odometry->push_back(kiss.poses.at(std::stoul(f)));
    }
  }
  static void TearDownTestSuite() {
    delete scans;
    delete odometry;
  }
  static Config config() {
    Config c;
    c.retrieval.exclude_recent = 1;  // four scans: every older one is a candidate
    return c;
  }
  static std::vector<LabeledCloud>* scans;
  static std::vector<Eigen::Isometry3d>* odometry;
};
std::vector<LabeledCloud>* Pipeline::scans;
std::vector<Eigen::Isometry3d>* Pipeline::odometry;

TEST_F(Pipeline, DetectsWhatTheDetectorDetectsAndMakesItsEdge) {
  LoopClosingPipeline closer(config());
  LoopDetector detector(config());
  FrameResult r;
  for (size_t i = 0; i < scans->size(); ++i) {
    const PipelineFrame f = closer.addScan((*scans)[i]);
    r = detector.process((*scans)[i]);
    EXPECT_EQ(f.index, static_cast<int>(i));
    EXPECT_EQ(f.detection.num_nodes, r.num_nodes);
    EXPECT_EQ(f.detection.is_loop, r.is_loop);
    EXPECT_EQ(f.loop.has_value(), r.is_loop);
    EXPECT_FALSE(f.solved);  // no poses: detection only
  }
  // The one revisit, 4501 → 52, as `sgtllc pair` finds it; frames named by their index when no name is given.
  ASSERT_EQ(closer.loops().size(), 1u);
  const pipeline::ClosingLoop& loop = closer.loops()[0];
  EXPECT_EQ(loop.query, "000003");
  EXPECT_EQ(loop.match, "000000");
  EXPECT_EQ(loop.edge.from, 0);
  EXPECT_EQ(loop.edge.to, 3);
  EXPECT_EQ(loop.edge.kind, backend::EdgeKind::kLoop);
  EXPECT_NEAR(loop.score, 0.64, 1e-9);
  // The detector's pose, and the information of its inlier centres.
  const Candidate* c = r.loop();
  ASSERT_NE(c, nullptr);
  EXPECT_EQ(c->match.T_match_query, loop.edge.T_from_to.matrix());
  const backend::Edge edge = backend::loopEdge(0, 3, c->match, detector.database().nodes(3),
                                               detector.database().nodes(0), config().backend.loops);
  EXPECT_EQ(edge.information, loop.edge.information);
  EXPECT_GT(edge.information.trace(), 0.0);
  EXPECT_TRUE(loop.has_information);
  EXPECT_TRUE(closer.poses().empty());
  EXPECT_THROW(closer.finish(), Error);  // no odometry: nothing to solve
}

TEST_F(Pipeline, BatchFinishIsTheBackEndOverTheOdometryAndTheLoops) {
  LoopClosingPipeline closer(config());
  for (size_t i = 0; i < scans->size(); ++i) closer.addScan((*scans)[i], (*odometry)[i], kFrames[i]);
  ASSERT_EQ(closer.loops().size(), 1u);
  EXPECT_EQ(closer.loops()[0].query, "004501");
  EXPECT_EQ(closer.loops()[0].match, "000052");
  // Before finish() the poses are the odometry, rotations made exactly orthonormal.
  ASSERT_EQ(closer.poses().size(), 4u);
  for (size_t i = 0; i < 4; ++i) {
    EXPECT_TRUE(closer.poses()[i].isApprox((*odometry)[i], 1e-6));
    const Eigen::Matrix3d R = closer.poses()[i].rotation();
    EXPECT_LT((R.transpose() * R - Eigen::Matrix3d::Identity()).norm(), 1e-14);
  }
  backend::PoseGraph graph = backend::odometryGraph(closer.odometry(), config().backend.odometry);
  graph.edges.push_back(closer.loops()[0].edge);
  const backend::BackendResult reference = backend::optimize(graph, config().backend);
  const pipeline::Closing& closing = closer.finish();
  EXPECT_EQ(closing.result.num_accepted, 1);
  ASSERT_EQ(closing.poses.size(), 4u);
  for (size_t i = 0; i < 4; ++i) EXPECT_TRUE(closing.poses[i].isApprox(reference.poses[i], 0.0));
  EXPECT_EQ(&closer.poses(), &closer.closing()->poses);
  // 4501 is 2.96 m from 52 by the ground truth; KISS-ICP's odometry, with no loop closure, drifted to 12.4 m.
  EXPECT_GT((odometry->at(3).translation() - odometry->at(0).translation()).norm(), 12.0);
  EXPECT_NEAR((closing.poses[3].translation() - closing.poses[0].translation()).norm(), 2.96, 0.05);
  const map::Map m = closer.map();
  EXPECT_EQ(m.names, kFrames);
  ASSERT_EQ(m.poses.size(), 4u);
  EXPECT_TRUE(m.poses[3].isApprox(closing.poses[3].matrix(), 0.0));
  EXPECT_THROW(closer.finish(), Error);
  EXPECT_THROW(closer.addScan((*scans)[0], (*odometry)[0]), Error);
  EXPECT_EQ(closer.numFrames(), 4);
}

TEST_F(Pipeline, OnlineReSolvesAtTheLoopAndEndsAtTheBatchSolution) {
  LoopClosingPipeline batch(config()), online(config(), PipelineOptions{true, 1});
  for (size_t i = 0; i < scans->size(); ++i) {
    batch.addScan((*scans)[i], (*odometry)[i]);
    const PipelineFrame f = online.addScan((*scans)[i], (*odometry)[i]);
    EXPECT_EQ(f.solved, i == 3);
    EXPECT_EQ(f.update != nullptr, i == 3);
    if (f.update) {
      EXPECT_EQ(f.update->num_accepted, 1);
      // The re-solve moved the newest frame: poses() is the online estimate now.
      EXPECT_FALSE(online.poses()[3].isApprox(online.odometry()[3], 1e-6));
    }
  }
  const pipeline::Closing& a = batch.finish();
  const pipeline::Closing& b = online.finish();
  ASSERT_EQ(b.online_solve_cpu_ms.size(), 1u);
  for (size_t i = 0; i < 4; ++i) EXPECT_LT((a.poses[i].translation() - b.poses[i].translation()).norm(), 1e-3);
}

TEST_F(Pipeline, GeometricLabellerIgnoresTheScansLabels) {
  Config c = config();
  c.labeller.source = LabelSource::kGeometric;
  LoopClosingPipeline with_labels(c), without(c);
  LabeledCloud bare;
  bare.points = (*scans)[0].points;
  const PipelineFrame a = with_labels.addScan((*scans)[0]);
  const PipelineFrame b = without.addScan(bare);
  EXPECT_GT(a.detection.num_nodes, 5);
  EXPECT_EQ(a.detection.num_nodes, b.detection.num_nodes);
  const std::vector<Node>& na = with_labels.detector().database().nodes(0);
  const std::vector<Node>& nb = without.detector().database().nodes(0);
  for (size_t k = 0; k < na.size(); ++k) {
    EXPECT_EQ(na[k].centre, nb[k].centre);
    EXPECT_EQ(na[k].label, nb[k].label);
  }
}

TEST_F(Pipeline, AccumulatesScansAsTheAccumulatorMergesThem) {
  LoopClosingPipeline accumulating(config(), PipelineOptions{false, 2}), merged_by_hand(config());
  ScanAccumulator buffer(2);
  for (size_t i = 0; i < 2; ++i) {
    const PipelineFrame a = accumulating.addScan((*scans)[i], (*odometry)[i]);
    const PipelineFrame b = merged_by_hand.addScan(buffer.add((*scans)[i], pipeline::orthonormalised((*odometry)[i])),
                                                   (*odometry)[i]);
    EXPECT_EQ(a.detection.num_nodes, b.detection.num_nodes);
  }
  EXPECT_GT(accumulating.detector().database().nodes(1).size(), 0u);
  const std::vector<Node>& na = accumulating.detector().database().nodes(1);
  const std::vector<Node>& nb = merged_by_hand.detector().database().nodes(1);
  ASSERT_EQ(na.size(), nb.size());
  for (size_t k = 0; k < na.size(); ++k) EXPECT_EQ(na[k].centre, nb[k].centre);
  EXPECT_THROW(accumulating.addScan((*scans)[2]), Error);  // accumulating needs the pose
  EXPECT_THROW(LoopClosingPipeline(config(), PipelineOptions{false, 0}), Error);
}

TEST_F(Pipeline, RefusesInputItCannotUseAndKeepsNoneOfIt) {
  {
    LoopClosingPipeline closer(config());
    closer.addNodes({}, (*odometry)[0]);
    EXPECT_THROW(closer.addNodes({}), Error);  // the frames before had a pose
    Eigen::Isometry3d bad = (*odometry)[1];
    bad.translation().x() = std::nan("");
    EXPECT_THROW(closer.addNodes({}, bad), Error);
    // Too many nodes: the detector refuses the frame, and its pose is not kept either.
    std::vector<Node> many(static_cast<size_t>(config().graph.max_nodes) + 1);
    EXPECT_THROW(closer.addNodes(many, (*odometry)[1]), Error);
    EXPECT_EQ(closer.numFrames(), 1);
    EXPECT_EQ(closer.odometry().size(), 1u);
    EXPECT_EQ(closer.names().size(), 1u);
  }
  {
    LoopClosingPipeline closer(config());
    closer.addNodes({});
    EXPECT_THROW(closer.addNodes({}, (*odometry)[1]), Error);  // the frames before had none
    LabeledCloud unlabelled;
    unlabelled.points = (*scans)[0].points;
    try {
      closer.addScan(unlabelled);
      FAIL() << "a scan without labels was taken";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("labeller.source is geometric"), std::string::npos) << e.what();
    }
  }
  LoopClosingPipeline online(config(), PipelineOptions{true, 1});
  EXPECT_THROW(online.addNodes({}), Error);  // online solving needs the poses
  EXPECT_EQ(online.numFrames(), 0);
}

}  // namespace
}  // namespace sgtllc
