// SPDX-License-Identifier: MIT
// An evolve run's output folder: one run at a time (an exclusive lock naming its holder), a run
// is never replaced by accident (--resume or --force), the checkpoint is written last so that a
// kill or a failed write never leaves the log behind it, and no run file may replace an input.
#include <filesystem>
#include <mutex>
#include <unistd.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "app/cli.hpp"
#include "evolve/atomic_write.hpp"
#include "evolve/checkpoint.hpp"
#include "evolve/evolve_config.hpp"
#include "evolve/folder_lock.hpp"
#include "evolve/objective.hpp"
#include "evolve/runner.hpp"
#include "evolve_test_support.hpp"
#include "sim/config_error.hpp"
#include "tests/app/cli_support.hpp"

namespace swarmpath::evolve {
namespace {

namespace fs = std::filesystem;
using app::cli_support::cli;
using testing::read_text;
using testing::scratch;
using testing::write_text;

std::vector<std::string> evolve_args(const fs::path& config, const fs::path& out,
                                     std::vector<std::string> extra = {}) {
  std::vector<std::string> args = {"evolve",    "--config", config.string(), "--out", out.string(),
                                   "--threads", "2",        "--no-wall-time"};
  args.insert(args.end(), extra.begin(), extra.end());
  return args;
}

// every file of a folder (recursively, the lock file aside) with its bytes
std::map<std::string, std::string> folder_files(const fs::path& dir) {
  std::map<std::string, std::string> files;
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    if (e.is_regular_file() && e.path().filename() != FolderLock::kFileName) {
      files[fs::relative(e.path(), dir).string()] = read_text(e.path());
    }
  }
  return files;
}

// dir/tiny.toml (two generations) run straight through into dir/straight, and stopped after its
// first generation in `stopped`
void straight_and_stopped(const fs::path& dir, const fs::path& stopped) {
  write_text(dir / "tiny.toml", testing::tiny_config("random", 2));
  ASSERT_EQ(cli(evolve_args(dir / "tiny.toml", dir / "straight")).code, 0);
  ASSERT_EQ(cli(evolve_args(dir / "tiny.toml", stopped, {"--generations", "1"})).code, 0);
}

// a resumed run's folder ends byte for byte as an uninterrupted run's (run.json's thread count aside)
void expect_same_run(const fs::path& resumed, const fs::path& straight) {
  for (const char* f : {"log.csv", "checkpoint.json", "best.toml", "fitness.svg"}) {
    EXPECT_EQ(read_text(resumed / f), read_text(straight / f)) << f;
  }
  EXPECT_EQ(testing::run_json_text(resumed), testing::run_json_text(straight));
}

TEST(FolderLock, ASecondLockOnTheSameFolderFailsNamingTheHolder) {
  const fs::path dir = scratch("locked") / "out";
  {
    const FolderLock first(dir.string(), "evolve of first.toml");
    EXPECT_TRUE(fs::is_directory(dir));
    try {
      const FolderLock second(dir.string(), "evolve of second.toml");
      ADD_FAILURE() << "two locks on one folder";
    } catch (const sim::ConfigError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find("pid " + std::to_string(::getpid()) + " on host "), std::string::npos) << what;
      EXPECT_NE(what.find(" since 20"), std::string::npos) << what;  // the start time, UTC
      EXPECT_NE(what.find("evolve of first.toml"), std::string::npos) << what;
      EXPECT_EQ(what.rfind(dir.string() + ": ", 0), 0u) << what;
    }
  }
  // released with its holder: the folder can be locked again
  EXPECT_NO_THROW(FolderLock(dir.string(), "evolve of third.toml"));
}

TEST(RunFolder, ASecondEvolveIntoALockedFolderExitsTwoNamingTheHolder) {
  const fs::path dir = scratch("busy");
  write_text(dir / "tiny.toml", testing::tiny_config("random", 1));
  const FolderLock held((dir / "out").string(), "evolve of the first run");
  const app::cli_support::CliResult r = cli(evolve_args(dir / "tiny.toml", dir / "out"));
  EXPECT_EQ(r.code, app::kExitBadInput) << r.err;
  EXPECT_NE(r.err.find("another run is writing into this folder (pid " + std::to_string(::getpid())),
            std::string::npos)
      << r.err;
  EXPECT_FALSE(fs::exists(dir / "out" / "checkpoint.json"));
}

TEST(RunFolder, AFinishedRunIsNeverReplacedWithoutResumeOrForce) {
  const fs::path dir = scratch("finished");
  write_text(dir / "tiny.toml", testing::tiny_config("random", 1));
  const fs::path out = dir / "out";
  ASSERT_EQ(cli(evolve_args(dir / "tiny.toml", out)).code, 0);
  const auto before = folder_files(out);
  ASSERT_TRUE(before.count("best.toml"));
  // forgetting --resume: refused before anything is written
  app::cli_support::CliResult r = cli(evolve_args(dir / "tiny.toml", out));
  EXPECT_EQ(r.code, app::kExitBadInput) << r.err;
  for (const char* word : {"--resume", "--force", "generation 1"})
    EXPECT_NE(r.err.find(word), std::string::npos) << word << "\n" << r.err;
  EXPECT_EQ(folder_files(out), before);
  // a started run (a checkpoint, nothing else) is refused too
  const fs::path started = dir / "started";
  fs::create_directories(started);
  fs::copy_file(out / "checkpoint.json", started / "checkpoint.json");
  EXPECT_EQ(cli(evolve_args(dir / "tiny.toml", started)).code, app::kExitBadInput);
  // --force starts afresh and keeps the previous run's files under replaced/
  r = cli(evolve_args(dir / "tiny.toml", out, {"--force"}));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("replaced/"), std::string::npos) << r.err;
  std::vector<fs::path> kept;
  for (const auto& e : fs::directory_iterator(out / "replaced")) kept.push_back(e.path());
  ASSERT_EQ(kept.size(), 1u);
  EXPECT_EQ(read_text(kept[0] / "best.toml"), before.at("best.toml"));
  EXPECT_EQ(read_text(kept[0] / "checkpoint.json"), before.at("checkpoint.json"));
  EXPECT_EQ(read_text(out / "best.toml"), before.at("best.toml"));  // the same config, the same run
  // --resume and --force contradict each other
  EXPECT_EQ(cli(evolve_args(dir / "tiny.toml", out, {"--resume", "--force"})).code, app::kExitBadInput);
}

TEST(RunFolder, AFailedWriteOnTheLastGenerationLeavesACheckpointThatReRunsIt) {
  const fs::path dir = scratch("order");
  const fs::path straight = dir / "straight", broken = dir / "broken";
  ASSERT_NO_FATAL_FAILURE(straight_and_stopped(dir, broken));
  // log.csv cannot be replaced during the last generation (a folder stands in its way)
  fs::remove(broken / "log.csv");
  fs::create_directories(broken / "log.csv");
  app::cli_support::CliResult r = cli(evolve_args(dir / "tiny.toml", broken, {"--resume"}));
  EXPECT_EQ(r.code, app::kExitFailure) << r.err;
  EXPECT_NE(r.err.find("cannot write " + (broken / "log.csv").string()), std::string::npos) << r.err;
  // the checkpoint still stands before the generation whose log row is missing ...
  EXPECT_EQ(read_checkpoint((broken / "checkpoint.json").string()).generation, 1);
  // ... so that a resume re-runs it and the folder ends as an uninterrupted run's
  fs::remove(broken / "log.csv");
  r = cli(evolve_args(dir / "tiny.toml", broken, {"--resume"}));
  ASSERT_EQ(r.code, 0) << r.err;
  expect_same_run(broken, straight);
}

TEST(RunFolder, ALogThatCannotBeWrittenInTheLastGenerationLeavesThePreviousCheckpoint) {
  // the failure strikes while the last generation runs, after the resume has rewritten the log:
  // with checkpoint.json written before log.csv, the checkpoint would already say "finished"
  const fs::path dir = scratch("last");
  const fs::path straight = dir / "straight", broken = dir / "broken";
  ASSERT_NO_FATAL_FAILURE(straight_and_stopped(dir, broken));
  const EvolveConfig c = load_evolve_config((dir / "tiny.toml").string());
  const SwarmObjective f(c);
  RunOptions o = testing::test_options(broken, 2, 2, true);
  std::once_flag block;
  o.progress = [&](std::size_t, std::size_t) {
    std::call_once(block, [&] {
      fs::remove(broken / "log.csv");
      fs::create_directories(broken / "log.csv" / "in-the-way");
    });
  };
  try {
    (void)run_evolution(c, f, o);
    ADD_FAILURE() << "the run wrote past a log.csv it could not replace";
  } catch (const WriteError& e) {
    EXPECT_EQ(e.path(), (broken / "log.csv").string()) << e.what();
  }
  EXPECT_EQ(read_checkpoint((broken / "checkpoint.json").string()).generation, 1);
  // the resume re-runs the last generation and ends as the uninterrupted run
  fs::remove_all(broken / "log.csv");
  const app::cli_support::CliResult r = cli(evolve_args(dir / "tiny.toml", broken, {"--resume"}));
  ASSERT_EQ(r.code, 0) << r.err;
  expect_same_run(broken, straight);
}

TEST(RunFolder, AResumeRewritesALogThatRanAheadOfTheCheckpoint) {
  const fs::path dir = scratch("ahead");
  write_text(dir / "tiny.toml", testing::tiny_config("random", 2));
  const fs::path out = dir / "out";
  ASSERT_EQ(cli(evolve_args(dir / "tiny.toml", out)).code, 0);
  const std::string log = read_text(out / "log.csv");
  // a kill between log.csv and checkpoint.json: the log holds a row the checkpoint does not
  write_text(out / "log.csv", log + "2,9,9,0,9,0,12,0\n");
  ASSERT_EQ(cli(evolve_args(dir / "tiny.toml", out, {"--resume"})).code, 0);
  EXPECT_EQ(read_text(out / "log.csv"), log);
}

TEST(RunFolder, AKillInTheFirstGenerationBeforeAnyCheckpointResumesFromTheStart) {
  const fs::path dir = scratch("first");
  const fs::path straight = dir / "straight", killed = dir / "killed";
  ASSERT_NO_FATAL_FAILURE(straight_and_stopped(dir, killed));
  // what a kill between log.csv and the first checkpoint.json leaves: the first generation's log
  // and plot, no checkpoint
  for (const char* f : {"checkpoint.json", "run.json", "best.toml"}) fs::remove(killed / f);
  ASSERT_TRUE(fs::exists(killed / "log.csv"));
  // a fresh start is refused (the files are an earlier run's), saying how far it got ...
  app::cli_support::CliResult r = cli(evolve_args(dir / "tiny.toml", killed));
  EXPECT_EQ(r.code, app::kExitBadInput) << r.err;
  for (const char* word : {"stopped in its first generation", "--resume"})
    EXPECT_NE(r.err.find(word), std::string::npos) << word << "\n" << r.err;
  // ... and --resume, which that message offers, runs it from generation 0 to the same end
  r = cli(evolve_args(dir / "tiny.toml", killed, {"--resume"}));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("starting at generation 0"), std::string::npos) << r.err;
  expect_same_run(killed, straight);
  // a folder with no run at all still has nothing to resume
  const fs::path empty = dir / "empty";
  fs::create_directories(empty);
  r = cli(evolve_args(dir / "tiny.toml", empty, {"--resume"}));
  EXPECT_EQ(r.code, app::kExitBadInput) << r.err;
  EXPECT_NE(r.err.find("no checkpoint here"), std::string::npos) << r.err;
}

TEST(RunFolder, NoRunFileMayReplaceAnInputOfTheRun) {
  const fs::path dir = scratch("inputs");
  const fs::path out = dir / "out";
  fs::create_directories(out);
  // the base params are the best.toml of an earlier run in the same folder
  fs::copy_file(testing::source("genomes/default.toml"), out / "best.toml");
  std::string text = testing::tiny_config("random", 1);
  text = testing::replaced(text, testing::source("genomes/default.toml"), (out / "best.toml").string());
  write_text(dir / "tiny.toml", text);
  const std::string before = read_text(out / "best.toml");
  const app::cli_support::CliResult r = cli(evolve_args(dir / "tiny.toml", out, {"--force"}));
  EXPECT_EQ(r.code, app::kExitBadInput) << r.err;
  EXPECT_NE(r.err.find("best.toml"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("params"), std::string::npos) << r.err;
  EXPECT_EQ(read_text(out / "best.toml"), before);
  EXPECT_FALSE(fs::exists(out / "checkpoint.json"));
}

TEST(RunFolder, OutNamingAFileIsABadInputNamingTheOption) {
  const fs::path dir = scratch("file");
  write_text(dir / "tiny.toml", testing::tiny_config("random", 1));
  write_text(dir / "notes.txt", "mine\n");
  const app::cli_support::CliResult r = cli(evolve_args(dir / "tiny.toml", dir / "notes.txt"));
  EXPECT_EQ(r.code, app::kExitBadInput) << r.err;
  EXPECT_NE(r.err.find("--out: " + (dir / "notes.txt").string() + " is a file"), std::string::npos) << r.err;
  EXPECT_EQ(read_text(dir / "notes.txt"), "mine\n");
}

}  // namespace
}  // namespace swarmpath::evolve
