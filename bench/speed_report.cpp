// SPDX-License-Identifier: MIT
// The speed table against ARGoS (bench/workloads.hpp): each workload's whole run (world set-up
// included) on one core, its CPU time the best of --repeat runs (as the first figures against ARGoS
// were taken; the median beside it), the repetitions interleaved so that a host's slow and fast
// minutes fall on every workload alike. Prints a markdown table with
// ARGoS's figures and the targets beside ours, the growth of the cost per robot-tick from 100 to
// 1 000 robots and task allocation's cost per robot-tick over path formation's.
//
//   build/release/bench/speed_report [--repeat 3] [--only NAME,...]
//   build/release/bench/speed_report --once NAME     (one run, for callgrind's instruction count)
//   ... --rab-to-all   every message to every robot that listens (the medium before it sorted
//                      messages by kind; the same results, for comparing the cost)
//
// ARGoS does 10 physics sub-steps a tick, swarmpath one Box2D step: every ratio says so.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <limits>
#include <string>
#include <unistd.h>
#include <vector>

#include "workloads.hpp"

namespace {

using namespace swarmpath;

double cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

std::string host_cpu() {
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("model name", 0) == 0) {
      const auto colon = line.find(':');
      return colon == std::string::npos ? line : line.substr(colon + 2);
    }
  }
  return "unknown CPU";
}

std::string host_name() {
  char host[256] = {};
  if (::gethostname(host, sizeof host - 1) != 0) return "unknown host";
  return host;
}

struct Result {
  const bench::Workload* w = nullptr;
  double best = std::numeric_limits<double>::infinity();  // CPU seconds
  std::vector<double> times;                              // every repetition's CPU seconds
  std::int64_t ticks = 0;
  int robots = 0;
  std::uint64_t state_hash = 0;
  bool success = false;

  double robot_ticks() const { return static_cast<double>(ticks) * robots; }

  double rate() const { return robot_ticks() / best; }

  double median() const {
    std::vector<double> t = times;
    std::sort(t.begin(), t.end());
    const std::size_t k = t.size() / 2;
    return t.size() % 2 == 1 ? t[k] : 0.5 * (t[k - 1] + t[k]);
  }
};

int usage() {
  std::fprintf(
      stderr,
      "usage: speed_report [--repeat N (default 3)] [--only NAME,...] | --once NAME; [--rab-to-all]\n"
      "workloads:");
  for (const bench::Workload& w : bench::workloads()) std::fprintf(stderr, " %s", w.name.c_str());
  std::fprintf(stderr, "\n");
  return 2;
}

std::string fmt_rate(double r) {
  char buf[32];
  if (r >= 1e6) {
    std::snprintf(buf, sizeof buf, "%.2f M", r / 1e6);
  } else {
    std::snprintf(buf, sizeof buf, "%.0f k", r / 1e3);
  }
  return buf;
}

}  // namespace

int main(int argc, char** argv) {
  int repeat = 3;
  std::string only;
  std::string once;
  bool rab_by_kind = true;
  for (int a = 1; a < argc; ++a) {
    const std::string arg = argv[a];
    if (arg == "--repeat" && a + 1 < argc) {
      repeat = std::atoi(argv[++a]);
    } else if (arg == "--only" && a + 1 < argc) {
      only = std::string(",") + argv[++a] + ",";
    } else if (arg == "--once" && a + 1 < argc) {
      once = argv[++a];
    } else if (arg == "--rab-to-all") {
      rab_by_kind = false;
    } else {
      return usage();
    }
  }
  if (repeat < 1) return usage();
  const std::vector<bench::Workload> all = bench::workloads();

  if (!once.empty()) {
    for (const bench::Workload& w : all) {
      if (w.name != once) continue;
      const sim::Metrics m = bench::run_workload(w, rab_by_kind);
      std::printf("%s: %d robots, %lld ticks, state_hash %016llx\n", w.name.c_str(), m.robots,
                  static_cast<long long>(m.ticks), static_cast<unsigned long long>(m.state_hash));
      return 0;
    }
    return usage();
  }

  std::vector<Result> results;
  for (const bench::Workload& w : all) {
    if (only.empty() || only.find("," + w.name + ",") != std::string::npos) {
      Result r;
      r.w = &w;
      results.push_back(r);
    }
  }
  if (results.empty()) return usage();
  std::fprintf(stderr, "speed_report: %zu workloads x %d repetitions, interleaved\n", results.size(), repeat);
  for (int r = 0; r < repeat; ++r) {
    for (Result& res : results) {
      const double start = cpu_seconds();
      const sim::Metrics m = bench::run_workload(*res.w, rab_by_kind);
      const double spent = cpu_seconds() - start;
      res.best = std::min(res.best, spent);
      res.times.push_back(spent);
      res.ticks = m.ticks;
      res.robots = m.robots;
      res.state_hash = m.state_hash;
      res.success = m.success;
      std::fprintf(stderr, "  %d/%d %-14s %.3f s CPU\n", r + 1, repeat, res.w->name.c_str(), spent);
    }
  }

  std::printf("Host: %s (%s); one core, CPU time of each whole run (set-up included), best of %d.\n",
              host_cpu().c_str(), host_name().c_str(), repeat);
  std::printf(
      "ARGoS 3 (one thread, 10 ticks/s, foot-bots) takes %d physics sub-steps a tick, swarmpath one Box2D "
      "step.\n\n",
      bench::kArgosPhysicsSubsteps);
  std::printf(
      "| workload | ticks | CPU s, best | CPU s, median | robot-ticks/s (best) | ARGoS | ratio (10 sub-steps "
      ": 1) | "
      "target | met |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|\n");
  for (const Result& res : results) {
    const bench::Workload& w = *res.w;
    const double ratio = res.rate() / w.argos_robot_ticks_per_s;
    char target[64];
    bool met = false;
    if (w.target_seconds > 0.0) {
      std::snprintf(target, sizeof target, "<= %.2f s", w.target_seconds);
      met = res.best <= w.target_seconds;
    } else {
      std::snprintf(target, sizeof target, ">= %s/s", fmt_rate(w.target_rate).c_str());
      met = res.rate() >= w.target_rate;
    }
    std::printf("| %s | %lld | %.3f | %.3f | %s | %.0f | %.0fx | %s | %s |\n", w.what.c_str(),
                static_cast<long long>(res.ticks), res.best, res.median(), fmt_rate(res.rate()).c_str(),
                w.argos_robot_ticks_per_s, ratio, target, met ? "yes" : "no");
  }
  const auto find = [&](const char* name) -> const Result* {
    for (const Result& res : results) {
      if (res.w->name == name) return &res;
    }
    return nullptr;
  };
  const Result* d100 = find("diffusion100");
  const Result* d1000 = find("diffusion1000");
  const Result* pf = find("pf_env4");
  const Result* ta = find("ta_env4");
  std::printf("\n");
  if (d100 != nullptr && d1000 != nullptr) {
    const double growth = d100->rate() / d1000->rate();
    std::printf("cost growth per robot-tick, 100 -> 1 000 robots: %.2fx (target <= 1.20x: %s)\n", growth,
                growth <= 1.2 ? "met" : "not met");
  }
  if (pf != nullptr && ta != nullptr) {
    const double per_tick = pf->rate() / ta->rate();
    std::printf("task allocation's cost per robot-tick over path formation's: %.2fx (target <= 1.30x: %s)\n",
                per_tick, per_tick <= 1.3 ? "met" : "not met");
  }
  std::printf("(ratios to ARGoS: ARGoS does %d physics sub-steps a tick, swarmpath one Box2D step)\n",
              bench::kArgosPhysicsSubsteps);
  for (const Result& res : results) {
    std::printf("%s: %d robots, %lld ticks, success %d, state_hash %016llx\n", res.w->name.c_str(),
                res.robots, static_cast<long long>(res.ticks), res.success ? 1 : 0,
                static_cast<unsigned long long>(res.state_hash));
  }
  return 0;
}
