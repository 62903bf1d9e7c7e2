// SPDX-License-Identifier: MIT
// Our own random numbers: xoshiro256** streams seeded by splitmix64, and our own distributions,
// because std::*_distribution results differ between standard-library versions.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>

namespace swarmpath::sim {

/// One splitmix64 step: advances `state` and returns a well-mixed 64-bit value.
constexpr std::uint64_t splitmix64(std::uint64_t& state) {
  std::uint64_t z = (state += 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

/// Mix several integers into one seed (order matters). Used to derive stream seeds
/// from (master seed, purpose, index, ...) without touching any global state.
constexpr std::uint64_t mix_seed(std::uint64_t a, std::uint64_t b) {
  std::uint64_t s = a ^ (b * 0xd1342543de82ef95ULL + 0x2545f4914f6cdd1dULL);
  std::uint64_t r = splitmix64(s);
  return splitmix64(r);
}

template <typename... Rest>
constexpr std::uint64_t mix_seed(std::uint64_t a, std::uint64_t b, Rest... rest) {
  return mix_seed(mix_seed(a, b), static_cast<std::uint64_t>(rest)...);
}

/// xoshiro256** (Blackman & Vigna). 32 bytes of state, serialisable as four integers.
class Rng {
 public:
  Rng() : Rng(0) {}

  explicit Rng(std::uint64_t seed) {
    std::uint64_t s = seed;
    for (auto& w : s_) w = splitmix64(s);
  }

  std::uint64_t next_u64() {
    const std::uint64_t result = rotl(s_[1] * 5, 7) * 9;
    const std::uint64_t t = s_[1] << 17;
    s_[2] ^= s_[0];
    s_[3] ^= s_[1];
    s_[1] ^= s_[2];
    s_[0] ^= s_[3];
    s_[2] ^= t;
    s_[3] = rotl(s_[3], 45);
    return result;
  }

  /// Uniform in [0, 1) with 53 random bits.
  double uniform() { return static_cast<double>(next_u64() >> 11) * 0x1.0p-53; }

  /// Uniform in [lo, hi).
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }

  /// Uniform integer in [0, n) by rejection (no modulo bias). n must be > 0.
  std::uint64_t below(std::uint64_t n) {
    const std::uint64_t limit = ~std::uint64_t{0} - (~std::uint64_t{0} % n);
    std::uint64_t x = next_u64();
    while (x >= limit) x = next_u64();
    return x % n;
  }

  /// True with probability p.
  bool bernoulli(double p) { return uniform() < p; }

  /// Standard normal by the Marsaglia polar method (pure arithmetic plus sqrt and log).
  /// The second variate of each pair is discarded so that the whole state is the four words.
  double normal() {
    double u, v, s;
    do {
      u = 2.0 * uniform() - 1.0;
      v = 2.0 * uniform() - 1.0;
      s = u * u + v * v;
    } while (s >= 1.0 || s == 0.0);
    return u * std::sqrt(-2.0 * std::log(s) / s);
  }

  using State = std::array<std::uint64_t, 4>;

  const State& state() const { return s_; }

  void set_state(const State& s) { s_ = s; }

 private:
  static constexpr std::uint64_t rotl(std::uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }

  State s_{};
};

}  // namespace swarmpath::sim
