// SPDX-License-Identifier: MIT
// The JSON pieces of optimiser states: exact doubles, non-finite values, generator words.
#include "evolve/optim/state_json.hpp"

#include <cstring>
#include <limits>

#include <gtest/gtest.h>

namespace swarmpath::evolve {
namespace {

double round_trip(double v) {
  const std::string text = nlohmann::json{{"v", number_to_json(v)}}.dump();
  return number_from_json(nlohmann::json::parse(text).at("v"));
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof(double)) == 0; }

TEST(StateJson, FiniteDoublesRoundTripBitForBit) {
  for (const double v : {0.0, -0.0, 0.1, 1.0 / 3.0, -2.5e-300, 4.9e-324, std::numeric_limits<double>::min(),
                         std::numeric_limits<double>::max(), std::numeric_limits<double>::lowest(),
                         std::nextafter(1.0, 2.0)}) {
    EXPECT_TRUE(same_bits(round_trip(v), v)) << v;
  }
  // random bit patterns across the whole range
  sim::Rng rng(17);
  int tested = 0;
  while (tested < 20000) {
    const std::uint64_t bits = rng.next_u64();
    double v;
    std::memcpy(&v, &bits, sizeof v);
    if (!std::isfinite(v)) continue;
    ASSERT_TRUE(same_bits(round_trip(v), v)) << bits;
    ++tested;
  }
}

TEST(StateJson, NonFiniteValuesRoundTrip) {
  EXPECT_EQ(round_trip(std::numeric_limits<double>::infinity()), std::numeric_limits<double>::infinity());
  EXPECT_EQ(round_trip(-std::numeric_limits<double>::infinity()), -std::numeric_limits<double>::infinity());
  EXPECT_TRUE(std::isnan(round_trip(std::nan(""))));
  EXPECT_THROW(number_from_json(nlohmann::json("infinity")), std::invalid_argument);
}

TEST(StateJson, GeneratorStateRoundTrips) {
  sim::Rng a(0xfeedULL);
  for (int i = 0; i < 5; ++i) a.next_u64();
  sim::Rng b;
  rng_from_json(nlohmann::json::parse(rng_to_json(a).dump()), b);
  EXPECT_EQ(a.state(), b.state());
  for (int i = 0; i < 100; ++i) EXPECT_EQ(a.next_u64(), b.next_u64());
}

}  // namespace
}  // namespace swarmpath::evolve
