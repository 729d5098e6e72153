// The loops CSV of `sgtllc run --out`: writer text, round trip with frame names → indices, edges, bad input.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "sgtllc/io/loops_csv.h"
#include "sgtllc/types.h"
#include "test_io_support.h"
#include "test_support.h"

namespace {

using sgtllc::Error;
using sgtllc::io::LoopRecord;
using ::testing::AllOf;
using ::testing::HasSubstr;

const std::string kHeader = "query,match,score,score_c,r11,r12,r13,tx,r21,r22,r23,ty,r31,r32,r33,tz\n";
const std::vector<std::string> kFrames = {"000050", "000051", "000052", "004500", "004501"};

class LoopsCsv : public sgtllc::test::TempDirTest {
 protected:
  std::string readError(const std::string& text) {
    const std::string file = write("loops.csv", text);
    return sgtllc::test::errorOf([&] { sgtllc::io::readLoopsCsv(file, kFrames); });
  }
};

LoopRecord revisit() {
  LoopRecord l;
  l.query = "004501";
  l.match = "000052";
  l.score = 0.8125;
  l.score_c = 0.5;
  l.T_match_query = sgtllc::test::rigid(0.3, 0.5, -0.2, Eigen::Vector3d(2.988495, 0.177681, 0.029293));
  return l;
}

TEST_F(LoopsCsv, TextIsTheRunCommandsFormat) {
  LoopRecord l;
  l.query = "000010";
  l.match = "000002";
  l.score = 0.5;
  l.score_c = 0.25;
  l.T_match_query(0, 3) = -1.5;
  EXPECT_EQ(sgtllc::io::loopsCsvText({l}),
            kHeader + "000010,000002,0.500000,0.250000,1.000000,0.000000,0.000000,-1.500000,0.000000,1.000000,"
                      "0.000000,0.000000,0.000000,0.000000,1.000000,0.000000\n");
  EXPECT_EQ(sgtllc::io::loopsCsvColumns().size(), 16u);
}

TEST_F(LoopsCsv, RoundTripMapsNamesToIndices) {
  const LoopRecord l = revisit();
  const std::string file = write("loops.csv", sgtllc::io::loopsCsvText({l, l}));
  const std::vector<LoopRecord> back = sgtllc::io::readLoopsCsv(file, kFrames);
  ASSERT_EQ(back.size(), 2u);
  EXPECT_EQ(back[0].query, "004501");
  EXPECT_EQ(back[0].query_index, 4);
  EXPECT_EQ(back[0].match_index, 2);
  EXPECT_DOUBLE_EQ(back[0].score, 0.8125);
  EXPECT_DOUBLE_EQ(back[0].score_c, 0.5);
  EXPECT_LE((back[0].T_match_query - l.T_match_query).cwiseAbs().maxCoeff(), 5e-7);  // six decimals

  const sgtllc::backend::Matrix6d info = 3.0 * sgtllc::backend::Matrix6d::Identity();
  const std::vector<sgtllc::backend::Edge> edges = sgtllc::io::loopEdges(back, info);
  ASSERT_EQ(edges.size(), 2u);
  EXPECT_EQ(edges[0].from, 2);  // the match
  EXPECT_EQ(edges[0].to, 4);    // the query: p_match = T_match_query · p_query
  EXPECT_EQ(edges[0].kind, sgtllc::backend::EdgeKind::kLoop);
  EXPECT_EQ(edges[0].information, info);
  const Eigen::Matrix3d R = edges[0].T_from_to.linear();
  EXPECT_LE((R.transpose() * R - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff(), 1e-14);
  EXPECT_LE((edges[0].T_from_to.matrix() - l.T_match_query).cwiseAbs().maxCoeff(), 2e-6);
  EXPECT_THROW(sgtllc::io::loopEdges({revisit()}, info), Error);  // no indices: not from the reader
}

// fuzz/regressions/loops_csv/translation_1e70.csv: numbers of 1e63 and more were cut short by the writer.
TEST_F(LoopsCsv, HugeNumbersAreWrittenWhole) {
  LoopRecord l = revisit();
  l.score = -1.5e308;
  l.T_match_query(0, 3) = 1e70;
  const std::string file = write("loops.csv", sgtllc::io::loopsCsvText({l}));
  const std::vector<LoopRecord> back = sgtllc::io::readLoopsCsv(file, kFrames);
  ASSERT_EQ(back.size(), 1u);
  EXPECT_EQ(back[0].score, -1.5e308);  // `%.6f` of an integer-valued double is exact
  EXPECT_EQ(back[0].T_match_query(0, 3), 1e70);
}

TEST_F(LoopsCsv, HeaderOnlyAndCrlfAreFine) {
  EXPECT_TRUE(sgtllc::io::readLoopsCsv(write("a.csv", kHeader), kFrames).empty());
  std::string crlf = sgtllc::io::loopsCsvText({revisit()});
  for (size_t p = crlf.find('\n'); p != std::string::npos; p = crlf.find('\n', p + 2)) crlf.insert(p, "\r");
  EXPECT_EQ(sgtllc::io::readLoopsCsv(write("b.csv", crlf), kFrames).size(), 1u);
}

TEST_F(LoopsCsv, UnknownFramesNameFileLineAndFrame) {
  LoopRecord l = revisit();
  l.query = "009999";
  EXPECT_THAT(readError(sgtllc::io::loopsCsvText({revisit(), l})),
              AllOf(HasSubstr("loops.csv:3: unknown query frame '009999'"), HasSubstr("5 frames")));
  l = revisit();
  l.match = "52";
  EXPECT_THAT(readError(sgtllc::io::loopsCsvText({l})), HasSubstr("loops.csv:2: unknown match frame '52'"));
  l.match = l.query;
  EXPECT_THAT(readError(sgtllc::io::loopsCsvText({l})), HasSubstr("loops.csv:2: loop of frame '004501' with itself"));
}

TEST_F(LoopsCsv, BadColumnsAndNumbers) {
  EXPECT_THAT(readError(kHeader + "004501,000052,0.5\n"), HasSubstr("loops.csv:2: 3 columns, expected 16"));
  std::string row = sgtllc::io::loopsCsvText({revisit()}).substr(kHeader.size());
  EXPECT_THAT(readError(kHeader + row.replace(row.find(",0.812500"), 9, ",abc")),
              HasSubstr("loops.csv:2: column score: 'abc' is not a finite number"));
  EXPECT_THAT(readError(kHeader + "004501,000052,0.5,0.5,1,0,0,nan,0,1,0,0,0,0,1,0\n"),
              HasSubstr("column tx: 'nan' is not a finite number"));
  EXPECT_THAT(readError(kHeader + "004501,000052,0.5,0.5,1,0,0,0,0,1,0,0,0,0,-1,0\n"),
              HasSubstr("loops.csv:2: r11..r33 is not a rotation"));
  EXPECT_THAT(readError("query,match,score\n"), HasSubstr("loops.csv:1: header 'query,match,score' is not"));
  EXPECT_THAT(readError(""), HasSubstr("loops.csv: empty file"));
}

}  // namespace
