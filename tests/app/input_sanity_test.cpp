// SPDX-License-Identifier: MIT
// Command lines that would run but mean nonsense are exit 2 with a message naming the option:
// seeds and thread counts out of range, a scenario or robot count listed twice, products that
// exhaust memory, an arena whose A* baseline finds no path; the paper's numbers are matched by a
// scenario's content, not its name; names with odd characters cannot break the outputs; and the
// messages point at what is wrong.
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "app/cli.hpp"
#include "app/paper_results.hpp"
#include "evolve/xml_escape.hpp"
#include "sim/hash.hpp"
#include "tests/app/cli_support.hpp"

namespace swarmpath::app {
namespace {

namespace fs = std::filesystem;
using Result = cli_support::CliResult;
using cli_support::cli;

using cli_support::short_chain;
using cli_support::source;

std::string env(int k) { return source("configs/scenarios/paper/env" + std::to_string(k) + ".toml"); }

fs::path scratch(const std::string& name) { return cli_support::test_scratch("sanity_test", name); }

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto pos = text.find(from);
  EXPECT_NE(pos, std::string::npos) << from;
  return text.replace(pos, from.size(), to);
}

void expect_bad(const std::vector<std::string>& args, const std::vector<std::string>& words) {
  const Result r = cli(args);
  EXPECT_EQ(r.code, kExitBadInput) << args[0] << "\n" << r.err;
  for (const std::string& w : words) EXPECT_NE(r.err.find(w), std::string::npos) << w << "\n" << r.err;
}

TEST(SeedsAndThreads, OutOfRangeValuesAreRefusedNotWrapped) {
  const std::vector<std::string> sim = {"simulate", "--scenario", short_chain(), "--robots", "4",
                                        "--ticks",  "1"};
  const auto with = [&](std::vector<std::string> extra) {
    std::vector<std::string> a = sim;
    a.insert(a.end(), extra.begin(), extra.end());
    return a;
  };
  expect_bad(with({"--seed", "-1"}), {"--seed", "0 to 18446744073709551615"});
  expect_bad(with({"--seed", "18446744073709551616"}), {"--seed"});
  expect_bad(with({"--seed", "99999999999999999999999"}), {"--seed"});
  expect_bad(with({"--seed", "1e3"}), {"--seed"});
  const Result top = cli(with({"--seed", "18446744073709551615", "--json"}));
  ASSERT_EQ(top.code, 0) << top.err;
  EXPECT_EQ(nlohmann::json::parse(top.out).at("seed").get<std::uint64_t>(), 18446744073709551615ULL);
  // the last seed of a grid must not wrap around to 0
  expect_bad({"table", "--scenarios", short_chain(), "--robots", "4", "--seeds", "3", "--seed-base",
              "18446744073709551614"},
             {"--seed-base", "wrap"});
  expect_bad({"evaluate", "--params", source("genomes/default.toml"), "--scenarios", short_chain(), "--seeds",
              "2", "--seed-base", "18446744073709551615"},
             {"--seed-base", "wrap"});
  for (const char* t : {"-1", "0", "1025"}) {
    expect_bad(with({"--threads", t}), {});
    expect_bad({"table", "--scenarios", short_chain(), "--robots", "4", "--seeds", "1", "--threads", t},
               {"--threads", "[1, 1024]"});
  }
}

TEST(Duplicates, AScenarioOrRobotCountListedTwiceIsRefused) {
  const fs::path dir = scratch("dup");
  fs::copy_file(short_chain(), dir / "copy.toml");
  expect_bad({"table", "--scenarios", short_chain(), short_chain(), "--robots", "4", "--seeds", "1"},
             {"--scenarios", "twice"});
  // the same file by another path, and an identical copy under another name
  expect_bad({"table", "--scenarios", short_chain(), source("tests/data/../data/short_chain.toml"),
              "--robots", "4", "--seeds", "1"},
             {"--scenarios", "twice"});
  expect_bad(
      {"table", "--scenarios", short_chain(), (dir / "copy.toml").string(), "--robots", "4", "--seeds", "1"},
      {"--scenarios", "the same scenario"});
  expect_bad({"table", "--scenarios", short_chain(), "--robots", "4,4", "--seeds", "1"},
             {"--robots", "twice"});
  expect_bad({"evaluate", "--params", source("genomes/default.toml"), "--scenarios", short_chain(),
              short_chain(), "--seeds", "1"},
             {"--scenarios", "twice"});
  // two different scenarios with one name would merge into one row of the table
  cli_support::write_file(dir / "other.toml", replaced(cli_support::read_file(short_chain()),
                                                       "goal = [1.8, 0.0]", "goal = [1.7, 0.0]"));
  expect_bad(
      {"table", "--scenarios", short_chain(), (dir / "other.toml").string(), "--robots", "4", "--seeds", "1"},
      {"--scenarios", "short_chain", "name"});
}

TEST(PaperNumbers, AreMatchedByTheArenaNotByItsName) {
  const fs::path dir = scratch("paper");
  // env4 with one obstacle moved, still named env4: not the paper's env4
  cli_support::write_file(dir / "env4.toml",
                          replaced(cli_support::read_file(env(4)), "radius = 0.5", "radius = 0.4"));
  // env1 under another name: the paper's env1 all the same
  cli_support::write_file(dir / "arena-one.toml", replaced(cli_support::read_file(env(1)), "name = \"env1\"",
                                                           "name = \"arena-one\""));
  const fs::path json = dir / "t.json";
  const Result r =
      cli({"table", "--scenarios", (dir / "env4.toml").string(), (dir / "arena-one.toml").string(),
           "--robots", "8", "--seeds", "1", "--ticks", "5", "--json", json.string()});
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(cli_support::read_file(json));
  ASSERT_EQ(j.at("environments").size(), 2u);
  const nlohmann::json& edited = j.at("environments")[0];
  const nlohmann::json& renamed = j.at("environments")[1];
  EXPECT_EQ(edited.at("scenario"), "env4");
  EXPECT_FALSE(edited.contains("paper")) << edited.dump();
  EXPECT_EQ(renamed.at("scenario"), "arena-one");
  ASSERT_TRUE(renamed.contains("paper")) << renamed.dump();
  EXPECT_EQ(renamed.at("paper").at("env"), 1);
  EXPECT_DOUBLE_EQ(renamed.at("paper").at("astar_tu").get<double>(), 100.0);
  // the markdown says why the edited env4 has no paper figures
  EXPECT_NE(r.out.find("| env4 (not the paper's env4: its arena differs) |"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("| arena-one (the paper's env1) |"), std::string::npos) << r.out;
}

TEST(PaperNumbers, EachShippedPaperArenaIsItsRow) {  // SPEC §5.1's eight rows
  for (int k = 1; k <= 8; ++k) {
    const sim::Scenario s = sim::load_scenario(env(k));
    const std::optional<PaperRow> row = paper_row(s);
    ASSERT_TRUE(row.has_value()) << "env" << k << ": its arena changed; its fingerprint is now 0x"
                                 << sim::to_hex(sim::arena_fingerprint(s)) << " (app/paper_results.hpp)";
    EXPECT_EQ(row->env, k);
  }
}

TEST(Outputs, OddCharactersInNamesCannotBreakTheCsvTheMarkdownOrThePictures) {
  const fs::path dir = scratch("names");
  cli_support::write_file(dir / "odd.toml",
                          replaced(cli_support::read_file(short_chain()), "name = \"short_chain\"",
                                   "name = \"a, \\\"b\\\" | <c> & d\""));
  const Result r = cli({"table", "--scenarios", (dir / "odd.toml").string(), "--robots", "4", "--seeds", "1",
                        "--ticks", "5", "--csv", (dir / "t.csv").string()});
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string csv = cli_support::read_file(dir / "t.csv");
  EXPECT_NE(csv.find("\n\"a, \"\"b\"\" | <c> & d\",4,1,"), std::string::npos) << csv;  // RFC 4180 quoting
  EXPECT_NE(r.out.find("| a, \"b\" \\| <c> & d |"), std::string::npos) << r.out;       // the pipe escaped
  const Result s = cli({"simulate", "--scenario", (dir / "odd.toml").string(), "--robots", "4", "--ticks",
                        "1", "--svg", (dir / "odd.svg").string()});
  ASSERT_EQ(s.code, 0) << s.err;
  EXPECT_NE(cli_support::read_file(dir / "odd.svg").find("a, &quot;b&quot; | &lt;c&gt; &amp; d"),
            std::string::npos);
}

TEST(Outputs, ControlCharactersNeverReachAnSvgOrXmlFile) {
  // XML 1.0 cannot hold C0 control characters even as references: they become U+FFFD
  EXPECT_EQ(evolve::xml_escape(std::string("a\0b\x01"
                                           "c\x1b[0m\x7f<d>",
                                           13)),
            "a\uFFFDb\uFFFDc\uFFFD[0m\uFFFD&lt;d&gt;");
  EXPECT_EQ(evolve::xml_escape("tab\tline\nreturn\r"), "tab\tline\nreturn\r");  // allowed in XML
  EXPECT_EQ(evolve::xml_escape("arène"), "arène");
}

TEST(ResourceLimits, AHeatMapOfTooManyCellsNamesTheOptionAndTheArena) {
  const fs::path dir = scratch("big");
  cli_support::write_file(
      dir / "big.toml",
      "name = \"big\"\nclass = \"open\"\nnest = [-2.0, 0.0]\ngoal = [2.0, 0.0]\n[arena]\nsize = [2000.0, "
      "2000.0]\n"
      "[deployment]\nsize = [1.0, 1.0]\nrobots = 4\n");
  expect_bad({"simulate", "--scenario", (dir / "big.toml").string(), "--ticks", "1", "--heatmap",
              (dir / "h.svg").string(), "--heatmap-cell", "1"},
             {"--heatmap-cell", "arena.size", "2000 x 2000 m", "limit 4000000", "--heatmap-cell >= 100"});
  EXPECT_FALSE(fs::exists(dir / "h.svg"));
}

TEST(Unreachable, AnArenaWhoseAStarBaselineFindsNoPathIsABadInput) {
  // a 16.5 cm slit: wide enough for the load check's conservative grid, too narrow for a robot (17 cm)
  const fs::path dir = scratch("slit");
  cli_support::write_file(dir / "slit.toml", cli_support::read_file(short_chain()) +
                                                 "\n[[box]]\ncenter = [0.0, 1.0825]\nsize = [0.2, 1.835]\n"
                                                 "[[box]]\ncenter = [0.0, -0.925]\nsize = [0.2, 1.85]\n");
  const std::string f = (dir / "slit.toml").string();
  const std::vector<std::string> words = {f, "A* baseline", "no path"};
  expect_bad({"table", "--scenarios", f, "--robots", "4", "--seeds", "1", "--ticks", "5"}, words);
  expect_bad({"evaluate", "--params", source("genomes/default.toml"), "--scenarios", f, "--robots", "4",
              "--seeds", "1", "--ticks", "5"},
             words);
}

TEST(Messages, AnUnknownCommandIsNamedWithTheNearestOne) {
  expect_bad({"simulat"}, {"unknown command 'simulat'", "did you mean 'simulate'"});
  expect_bad({"evalute", "--params", "x"}, {"unknown command 'evalute'", "did you mean 'evaluate'"});
  expect_bad({"fly"}, {"unknown command 'fly'", "swarmpath --help"});
}

TEST(Messages, AFolderAsAScenarioIsNamedAsSuch) {
  expect_bad({"simulate", "--scenario", source("configs/scenarios/paper")}, {"is a folder, not a file"});
  expect_bad({"astar", "--scenario", source("configs")}, {"is a folder, not a file"});
}

}  // namespace
}  // namespace swarmpath::app
