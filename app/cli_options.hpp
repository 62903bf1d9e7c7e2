// SPDX-License-Identifier: MIT
// Command-line options whose values CLI11 would take in silently wrong: a seed of -1 or 2^64 (both
// wrapped to 18446744073709551615), a thread count of -1. Every command registers them through
// these, so that an out-of-range value is exit 2 naming the option.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

namespace CLI {
class App;
class Option;
}  // namespace CLI

namespace swarmpath::app {

/// A 64-bit seed option: a whole number from 0 to 18446744073709551615 written in digits; anything
/// else (a sign, a fraction, an exponent, more than 2^64 - 1) is a parse error naming the option.
CLI::Option* add_seed_option(CLI::App& app, const std::string& name, std::uint64_t& seed,
                             const std::string& help);

/// --threads: a whole number in [1, 1024]; left out, every core (threads_or_all).
CLI::Option* add_threads_option(CLI::App& app, std::optional<int>& threads);

/// The thread count to use: the option's, or every core.
int threads_or_all(const std::optional<int>& threads);

/// The seeds base ... base + count - 1 must not wrap past 2^64 - 1: throws sim::ConfigError naming
/// `option` when they would.
void check_seed_range(const std::string& option, std::uint64_t base, std::int64_t count);

}  // namespace swarmpath::app
