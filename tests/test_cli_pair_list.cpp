// `sgtllc pair --list`: many pairs in one process give each pair what `sgtllc pair` gives it, and a pair that
// cannot be compared is reported without stopping the others.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sgtllc/io/csv.h"
#include "test_cli_support.h"
#include "test_kitti_support.h"

namespace sgtllc {
namespace {

using ::testing::HasSubstr;
using test::run;

std::string scan(const std::string& frame) { return test::dataPath("kitti/00/velodyne/" + frame + ".bin"); }

std::vector<std::vector<std::string>> csvRecords(const std::string& text) {
  io::CsvReader reader(text, "stdout");
  std::vector<std::vector<std::string>> out;
  for (std::vector<std::string> f; reader.next(f);) out.push_back(f);
  return out;
}

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

class CliPairList : public test::CliTempDirTest {
 protected:
  CliPairList() : CliTempDirTest("pair_list") {}
  std::string writeList(const std::string& text) {
    const std::string list = path("pairs.txt");
    std::ofstream(list) << text;
    return list;
  }
};

TEST_F(CliPairList, EachPairGetsWhatPairGivesIt) {
  const std::vector<std::pair<std::string, std::string>> pairs = {{"004501", "000052"}, {"000850", "000088"},
                                                                  {"000052", "004501"}};
  std::string text = "query,match\n";
  for (const auto& [q, m] : pairs) text += scan(q) + "," + scan(m) + "\n";
  const std::string list = writeList(text);
  const test::CliRun table = run("pair --list " + list, false);
  ASSERT_EQ(table.status, 0) << table.out;
  const auto rows = csvRecords(table.out);
  ASSERT_EQ(rows.size(), pairs.size() + 1);
  ASSERT_EQ(rows[0].size(), 24u);
  EXPECT_EQ(rows[0][3], "score");
  EXPECT_EQ(rows[0][11], "T00");
  const test::CliRun json_lines = run("pair --list " + list + " --json", false);
  ASSERT_EQ(json_lines.status, 0) << json_lines.out;
  const std::vector<std::string> objects = lines(json_lines.out);
  ASSERT_EQ(objects.size(), pairs.size());
  int loops = 0;
  for (size_t k = 0; k < pairs.size(); ++k) {
    const test::CliRun one = run("pair " + scan(pairs[k].first) + " " + scan(pairs[k].second) + " --json", false);
    ASSERT_EQ(one.status, 0) << one.out;
    const nlohmann::json single = nlohmann::json::parse(one.out);
    const nlohmann::json listed = nlohmann::json::parse(objects[k]);
    // The same object but for the time taken.
    nlohmann::json a = single, b = listed;
    a.erase("timing_ms");
    b.erase("timing_ms");
    EXPECT_EQ(a, b) << pairs[k].first;
    const std::vector<std::string>& row = rows[k + 1];
    ASSERT_EQ(row.size(), 24u);
    EXPECT_EQ(row[0], scan(pairs[k].first));
    EXPECT_EQ(row[2], single["loop"].get<bool>() ? "1" : "0");
    EXPECT_NEAR(std::stod(row[3]), single["score"].get<double>(), 1e-8);
    EXPECT_EQ(std::stoul(row[5]), single["inliers"].get<size_t>());
    EXPECT_EQ(row[8], single["path"].get<std::string>());
    EXPECT_EQ(row[9], single["rejection"].get<std::string>());
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 4; ++j) {
        EXPECT_NEAR(std::stod(row[11 + 4 * i + j]), single["T_match_query"][i][j].get<double>(), 1e-8);
      }
    }
    EXPECT_EQ(row[23], "");
    loops += single["loop"].get<bool>() ? 1 : 0;
  }
  EXPECT_EQ(loops, 2);  // the demo pair both ways; 850 and 88 are different places
}

TEST_F(CliPairList, APairThatCannotBeComparedIsReportedAndTheOthersGoOn) {
  const std::string list = writeList("missing.bin," + scan("000052") + "\n" + scan("004501") + "," +
                                     scan("000052") + "\n");
  const test::CliRun r = run("pair --list " + list, false);
  EXPECT_EQ(r.status, 1);
  const auto rows = csvRecords(r.out);
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[1][0], path("missing.bin"));
  EXPECT_THAT(rows[1][23], HasSubstr("missing.bin"));
  EXPECT_EQ(rows[1][2], "");
  EXPECT_EQ(rows[2][2], "1");
  const test::CliRun with_stderr = run("pair --list " + list);
  EXPECT_THAT(with_stderr.out, HasSubstr(list + ":1: cannot open " + path("missing.bin")));
  EXPECT_THAT(with_stderr.out, HasSubstr("1 of 2 pairs could not be compared"));
}

TEST_F(CliPairList, TheRowsDoNotDependOnTheThreads) {
  const std::string list = writeList(scan("004501") + "," + scan("000052") + "\nmissing.bin," + scan("000052") +
                                     "\n" + scan("000850") + "," + scan("000088") + "\n" + scan("000052") + "," +
                                     scan("004501") + "\n");
  const test::CliRun one = run("pair --list " + list + " --threads 1", false);
  EXPECT_EQ(one.status, 1);
  ASSERT_EQ(csvRecords(one.out).size(), 5u);
  for (const char* threads : {"2", "3"}) {
    const test::CliRun more = run("pair --list " + list + " --threads " + threads, false);
    EXPECT_EQ(more.status, 1);
    EXPECT_EQ(more.out, one.out) << threads << " threads";
  }
  const test::CliRun json = run("pair --list " + list + " --json --threads 3", false);
  const std::vector<std::string> objects = lines(json.out);
  ASSERT_EQ(objects.size(), 4u);
  EXPECT_EQ(nlohmann::json::parse(objects[1])["query"], path("missing.bin"));
  EXPECT_TRUE(nlohmann::json::parse(objects[3])["loop"].get<bool>());
}

TEST_F(CliPairList, AListTakesNoPairOfItsOwn) {
  const std::string list = writeList(scan("004501") + "," + scan("000052") + "\n");
  const test::CliRun both = run("pair --list " + list + " " + scan("004501"));
  EXPECT_EQ(both.status, 2);
  EXPECT_THAT(both.out, HasSubstr("no QUERY, MATCH"));
  const test::CliRun none = run("pair");
  EXPECT_EQ(none.status, 2);
  EXPECT_THAT(none.out, HasSubstr("give QUERY and MATCH, or --list FILE"));
  const test::CliRun empty = run("pair --list " + writeList("# no pairs\n"));
  EXPECT_EQ(empty.status, 1);
  EXPECT_THAT(empty.out, HasSubstr("no pair (one a line: QUERY,MATCH)"));
}

}  // namespace
}  // namespace sgtllc
