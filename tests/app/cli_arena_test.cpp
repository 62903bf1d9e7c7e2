// SPDX-License-Identifier: MIT
// swarmpath arena: generate writes the same scenario file for the same seed (and a picture),
// refuses bad families and parameters with exit code 2 naming the key, and `arena families`
// is what docs/arena-families.md lists.
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

#include <gtest/gtest.h>

#include "sim/scenario.hpp"
#include "tests/app/cli_support.hpp"

namespace swarmpath::app {
namespace {

using cli_support::cli;
namespace fs = std::filesystem;

fs::path temp_dir() { return cli_support::temp_dir("cli_arena_test"); }

std::string read(const fs::path& p) { return cli_support::read_file(p); }

TEST(CliArena, GenerateWritesTheSameFileForTheSameSeedAndAPicture) {
  const fs::path dir = temp_dir();
  const std::string a = (dir / "a.toml").string(), b = (dir / "b.toml").string(),
                    svg = (dir / "a.svg").string();
  auto r = cli({"arena", "generate", "--family", "wall-gap", "--seed", "7", "--set", "walls=2", "--out", a,
                "--svg", svg});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("wrote " + a), std::string::npos) << r.out;
  r = cli({"arena", "generate", "--family", "wall-gap", "--set", "walls=2", "--seed", "7", "--out", b});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(read(a), read(b));
  const sim::Scenario s = sim::load_scenario(a);
  EXPECT_EQ(s.name, "wall-gap-7");
  ASSERT_TRUE(s.origin.has_value());
  EXPECT_EQ(s.origin->seed, 7u);
  EXPECT_EQ(s.boxes.size(), 4u);  // two walls, each cut by its doorway
  EXPECT_NE(read(a).find("swarmpath arena generate --family wall-gap --seed 7 --set walls=2"),
            std::string::npos);
  const std::string picture = read(svg);
  EXPECT_EQ(picture.rfind("<svg", 0), 0u);
  EXPECT_NE(picture.find("A* 8-connected"), std::string::npos);
  // without --out the file goes to standard output
  r = cli({"arena", "generate", "--family", "wall-gap", "--seed", "7", "--set", "walls=2"});
  EXPECT_EQ(r.out, read(a));
}

TEST(CliArena, BadFamiliesAndParametersExitWithTwo) {
  auto r = cli({"arena", "generate", "--family", "lake"});
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--family: unknown arena family \"lake\""), std::string::npos) << r.err;
  r = cli({"arena", "generate", "--family", "rooms", "--set", "cols=9"});
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--set: cols: must lie in [1, 6] (got 9)"), std::string::npos) << r.err;
  r = cli({"arena", "generate", "--family", "rooms", "--set", "doors=2"});
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--set: doors: unknown parameter of family rooms"), std::string::npos) << r.err;
  r = cli({"arena", "generate", "--family", "open", "--set", "distance_min=27", "--set", "distance_max=28"});
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("no valid arena"), std::string::npos) << r.err;
  EXPECT_EQ(cli({"arena", "generate", "--family", "open", "--seed", "-1"}).code, 2);
  EXPECT_EQ(cli({"arena"}).code, 2);
}

TEST(CliArena, ABenchmarkSeedIsNamedAsOne) {
  const auto r = cli({"arena", "generate", "--family", "open", "--seed", "1000001"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("never screen or tune on it"), std::string::npos) << r.err;
  EXPECT_EQ(cli({"arena", "generate", "--family", "open", "--seed", "999999"}).err, "");
}

TEST(CliArena, TheDocsListTheFamiliesAsTheCommandDoes) {
  const auto r = cli({"arena", "families"});
  ASSERT_EQ(r.code, 0) << r.err;
  for (const char* f :
       {"open", "clutter", "wall-gap", "u-trap", "corridor", "serpentine", "rooms", "mixed"}) {
    EXPECT_NE(r.out.find(std::string("### ") + f + "\n"), std::string::npos) << f;
  }
  const std::string doc = read(fs::path(SWARMPATH_SOURCE_DIR) / "docs" / "arena-families.md");
  const std::string begin = "<!-- arena families: begin -->\n", end = "<!-- arena families: end -->";
  const auto b = doc.find(begin), e = doc.find(end);
  ASSERT_NE(b, std::string::npos);
  ASSERT_NE(e, std::string::npos);
  EXPECT_EQ(doc.substr(b + begin.size(), e - b - begin.size()), r.out)
      << "docs/arena-families.md is out of date: paste `swarmpath arena families` between its markers";
}

}  // namespace
}  // namespace swarmpath::app
