// SPDX-License-Identifier: MIT
// write_file_atomic: the previous file survives any failure, links stay links, devices are
// written in place, and no temporary file outlives a write.
#include "evolve/atomic_write.hpp"

#include <filesystem>

#include <gtest/gtest.h>

#include "evolve_test_support.hpp"

namespace swarmpath::evolve {
namespace {

namespace fs = std::filesystem;
using testing::read_text;
using testing::scratch;
using testing::write_text;

std::vector<std::string> names_in(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

TEST(AtomicWrite, ReplacesTheFileAndLeavesNoTemporaryFile) {
  const fs::path dir = scratch("w");
  write_file_atomic((dir / "a.json").string(), "one\n");
  write_file_atomic((dir / "a.json").string(), "two\n");
  EXPECT_EQ(read_text(dir / "a.json"), "two\n");
  EXPECT_EQ(names_in(dir), std::vector<std::string>{"a.json"});
}

TEST(AtomicWrite, AWriterThatFailsLeavesThePreviousFile) {
  const fs::path dir = scratch("w");
  write_text(dir / "a.csv", "previous\n");
  EXPECT_THROW(write_file_atomic((dir / "a.csv").string(),
                                 [](std::ostream& o) {
                                   o << "half";
                                   throw std::runtime_error("the writer failed");
                                 }),
               std::runtime_error);
  EXPECT_EQ(read_text(dir / "a.csv"), "previous\n");
  EXPECT_EQ(names_in(dir), std::vector<std::string>{"a.csv"});
}

TEST(AtomicWrite, FailuresNameTheFile) {
  const fs::path dir = scratch("w");
  fs::create_directories(dir / "folder.json");
  try {
    write_file_atomic((dir / "folder.json").string(), "x");
    ADD_FAILURE() << "wrote over a folder";
  } catch (const WriteError& e) {
    EXPECT_EQ(e.path(), (dir / "folder.json").string());
    EXPECT_EQ(std::string(e.what()), "cannot write " + (dir / "folder.json").string() + ": it is a folder");
  }
  try {
    write_file_atomic("/dev/full", "x");
    ADD_FAILURE() << "wrote to a full device";
  } catch (const WriteError& e) {
    EXPECT_EQ(std::string(e.what()), "cannot write /dev/full: No space left on device");
  }
  EXPECT_THROW(write_file_atomic((dir / "no" / "such.json").string(), "x"), WriteError);
}

TEST(AtomicWrite, ASymbolicLinkStaysALinkToTheNewContent) {
  const fs::path dir = scratch("w");
  write_text(dir / "real.toml", "old\n");
  fs::create_symlink("real.toml", dir / "link.toml");
  write_file_atomic((dir / "link.toml").string(), "new\n");
  EXPECT_TRUE(fs::is_symlink(dir / "link.toml"));
  EXPECT_EQ(read_text(dir / "real.toml"), "new\n");
}

TEST(AtomicWrite, RecognisesItsOwnTemporaryFiles) {
  EXPECT_TRUE(is_temporary_of("log.csv.1234-0.tmp", "log.csv"));
  EXPECT_FALSE(is_temporary_of("log.csv", "log.csv"));
  EXPECT_FALSE(is_temporary_of("log.csv.tmp", "log.csv"));
  EXPECT_FALSE(is_temporary_of("log.csv.notes.tmp", "log.csv"));
  EXPECT_FALSE(is_temporary_of("blog.csv.12-0.tmp", "log.csv"));
}

}  // namespace
}  // namespace swarmpath::evolve
