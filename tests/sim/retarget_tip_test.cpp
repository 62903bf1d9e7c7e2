// SPDX-License-Identifier: MIT
// retarget_tip [R] (docs/detours.md, row #5r): without task allocation a forming robot re-targets to the
// free RED nearest the nest in a straight line. Where the chain bends away from the nest (round a wall's
// end) a link inside it lies nearer the nest than its tip, and robots that reach the tip are drawn back
// into the chain, back off from there into the wall and lose their target. With the rule they re-target
// only to REDs that no RED light in view names as its parent: the chain's tips.
#include <vector>

#include <gtest/gtest.h>

#include "sim/controller.hpp"
#include "sim/controllers/path_formation.hpp"
#include "sim/step.hpp"
#include "test_support.hpp"

namespace swarmpath::sim {
namespace {

struct Outcome {
  bool success = false;
  std::int64_t ticks_to_form = -1;
  int lost = 0;  ///< forming robots that lost their target (rows #7 and #7h)
};

Outcome run_serpentine(const Params& p, std::uint64_t seed) {
  const Scenario s = load_scenario(test::source_path("tests/data/small_serpentine.toml"));
  const std::uint8_t row7 = pf_row_number("#7");
  const std::uint8_t row7h = pf_row_number("#7h");
  std::vector<std::int64_t> seen;
  int lost = 0;
  const Metrics m = run(p, s, Mode::kPathFormation, seed, [&](const World& at) {
    seen.resize(at.memory.size(), -1);
    for (std::size_t i = 0; i < at.memory.size(); ++i) {
      const PfMemory& pf = at.memory[i].pf;
      if (pf.fired_tick == seen[i]) continue;
      seen[i] = pf.fired_tick;
      if (pf.last_row == row7 || pf.last_row == row7h) ++lost;
    }
    return false;
  });
  return {m.success, m.ticks_to_form, lost};
}

// small_serpentine (two walls, the way winding through three chambers), 40 robots, seeds 1-8, path
// formation, the default genome: without the rule 5 of 8 runs form within T_max (20 000 ticks), with it
// all 8, each of the five sooner (12 379 -> 11 940, 13 301 -> 11 414, 13 553 -> 8 908, 17 725 -> 14 868,
// 11 562 -> 7 835 ticks)
TEST(RetargetTip, FormingRobotsKeepToTheTipsAndThePathFormsRoundTheWalls) {
  Params on;                    // the default: retarget_tip = true
  test::hasty_along_walls(on);  // as measured
  ASSERT_TRUE(on.retarget_tip);
  on.away_decay = 1.0;       // as measured: every trip under the full away field (with it on: 7 of 8)
  on.resume_search = false;  // ... explored from the nest
  on.share_after = 15000;    // ... and sightings told from tick 15 000
  test::pf_links_by_trail_slack(on);  // ... and links laid by trail_slack alone
  Params off = on;
  off.retarget_tip = false;
  int formed_off = 0, formed_on = 0, sooner = 0, both = 0, lost_off = 0, lost_on = 0;
  for (std::uint64_t seed = 1; seed <= 8; ++seed) {
    const Outcome a = run_serpentine(off, seed);
    const Outcome b = run_serpentine(on, seed);
    formed_off += a.success ? 1 : 0;
    formed_on += b.success ? 1 : 0;
    lost_off += a.lost;
    lost_on += b.lost;
    if (a.success && b.success) {
      ++both;
      if (b.ticks_to_form < a.ticks_to_form) ++sooner;
    }
  }
  EXPECT_EQ(formed_on, 8);
  EXPECT_LE(formed_off, 6);
  EXPECT_EQ(sooner, both);
  EXPECT_LT(lost_on, lost_off) << lost_off << " -> " << lost_on;
}

}  // namespace
}  // namespace swarmpath::sim
