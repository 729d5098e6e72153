// Configuration files refuse YAML anchors and aliases (an alias bomb is refused before anything expands), and an
// unknown key is answered with the nearest known one when it is a likely typo.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <string>

#include "sgtllc/io/config_yaml.h"
#include "test_config_support.h"
#include "test_support.h"

namespace sgtllc {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;
using ::testing::Not;

std::string errorOf(const std::string& yaml) { return test::configErrorOf(yaml); }

/// "Billion laughs": seven levels of nine aliases each, 4.8 million strings once expanded, in 254 bytes.
std::string aliasBomb() {
  std::string yaml = "a: &a [\"x\",\"x\",\"x\",\"x\",\"x\",\"x\",\"x\",\"x\",\"x\"]\n";
  for (char level = 'b'; level <= 'g'; ++level) {
    const std::string prev(1, static_cast<char>(level - 1));
    yaml += std::string(1, level) + ": &" + std::string(1, level) + " [";
    for (int k = 0; k < 9; ++k) yaml += (k ? ",*" : "*") + prev;
    yaml += "]\n";
  }
  return yaml;
}

constexpr const char* kRefused = "YAML aliases and anchors are not supported in sgtllc configs";

TEST(ConfigYamlAliases, TheAliasBombIsRefusedAtItsFirstAnchor) {
  EXPECT_EQ(aliasBomb().size(), 254u);
  EXPECT_EQ(errorOf(aliasBomb()), std::string("my.yaml:1: ") + kRefused);
  // Behind a valid key, and as a value of a real key: still refused, at the anchor's line.
  EXPECT_EQ(errorOf("threads: 2\n" + aliasBomb() + "graph: {sigma_d: *g}\n"), std::string("my.yaml:2: ") + kRefused);
}

TEST(ConfigYamlAliases, AnyAnchorOrAliasIsRefusedWithItsLine) {
  EXPECT_EQ(errorOf("graph:\n  sigma_d: &s 30\n  sigma_t: 2\n"), std::string("my.yaml:2: ") + kRefused);
  EXPECT_EQ(errorOf("graph: &g {sigma_d: 30}\n"), std::string("my.yaml:1: ") + kRefused);
  EXPECT_EQ(errorOf("labels:\n  extra_classes: &e []\n"), std::string("my.yaml:2: ") + kRefused);
  // An alias without its anchor: yaml-cpp's own message, on the alias's line.
  EXPECT_EQ(errorOf("threads: 2\n\ngraph: *undefined\n"),
            "my.yaml:3: malformed YAML: the referenced anchor is not defined");
  EXPECT_EQ(errorOf("a: &n\nb: 1\n"), std::string("my.yaml:1: ") + kRefused);  // an anchored null
}

TEST(ConfigYamlAliases, AmpersandsAndStarsInQuotesAndCommentsAreText) {
  // Not anchors: a comment, and a quoted name (here an unknown key, which says so instead).
  EXPECT_EQ(errorOf("# &a *a\nthreads: 2  # *b\n"), "(no error)");
  EXPECT_THAT(errorOf("\"&a *a\": 1\n"), HasSubstr("unknown key '&a *a'"));
}

// A fuzzer's input after which yaml-cpp's event parser reported new documents without end: only the first document
// is checked, as only the first is loaded (the file is a bundled config with bytes changed after its keys).
TEST(ConfigYamlAliases, MalformedTextAfterTheFirstDocumentEnds) {
  std::ifstream in(test::dataPath("../fuzz/regressions/config_yaml/endless_documents.yaml"), std::ios::binary);
  ASSERT_TRUE(in);
  const std::string yaml(std::istreambuf_iterator<char>(in), {});
  EXPECT_EQ(errorOf(yaml), "(no error)");
}

TEST(ConfigYamlSuggest, ATypoGetsTheNearestKey) {
  EXPECT_THAT(errorOf("graph:\n  sigma_dd: 3\n"),
              HasSubstr("my.yaml:2: unknown key 'graph.sigma_dd' (did you mean `graph.sigma_d`? run `sgtllc config`"));
  EXPECT_THAT(errorOf("grahp:\n  sigma_d: 3\n"), HasSubstr("unknown key 'grahp' (did you mean `graph`?"));
  EXPECT_THAT(errorOf("thraeds: 2\n"), HasSubstr("unknown key 'thraeds' (did you mean `threads`?"));
  EXPECT_THAT(errorOf("retrieval:\n  num_candidate: 3\n"), HasSubstr("did you mean `retrieval.num_candidates`?"));
  EXPECT_THAT(errorOf("cluster:\n  pole:\n    min_sze: 3\n"), HasSubstr("did you mean `cluster.pole.min_size`?"));
}

TEST(ConfigYamlSuggest, AFarKeyGetsNoGuess) {
  for (const char* yaml : {"zzzzzz: 1\n", "x: 1\n", "graph:\n  colour: 3\n", "retrieval:\n  kd: 1\n"}) {
    EXPECT_THAT(errorOf(yaml), AllOf(HasSubstr("unknown key"), Not(HasSubstr("did you mean")))) << yaml;
  }
}

TEST(ConfigYamlEscapes, AKeyWithControlBytesIsShownEscaped) {
  EXPECT_THAT(errorOf("\"\x1b[31mred\": 3\n"), AllOf(HasSubstr("unknown key '\\x1b[31mred'"), Not(HasSubstr("\x1b"))));
  EXPECT_THAT(errorOf("threads: \"\x1b[2J\"\n"), AllOf(HasSubstr("got '\\x1b[2J'"), Not(HasSubstr("\x1b"))));
}

}  // namespace
}  // namespace sgtllc
