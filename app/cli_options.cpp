// SPDX-License-Identifier: MIT
#include "cli_options.hpp"

#include <charconv>
#include <limits>

#include <CLI/CLI.hpp>
#include <omp.h>

#include "sim/config_error.hpp"

namespace swarmpath::app {

namespace {

constexpr int kMaxThreads = 1024;

// digits only, and within the type's range (std::from_chars reports the overflow CLI11 ignores)
template <typename T>
std::optional<T> whole_number(const std::string& text) {
  if (text.empty() || text.find_first_not_of("0123456789") != std::string::npos) return std::nullopt;
  T v{};
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return v;
}

}  // namespace

CLI::Option* add_seed_option(CLI::App& app, const std::string& name, std::uint64_t& seed,
                             const std::string& help) {
  return app
      .add_option_function<std::string>(
          name,
          [&seed, name](const std::string& text) {
            const std::optional<std::uint64_t> v = whole_number<std::uint64_t>(text);
            if (!v) {
              throw CLI::ValidationError(name, "must be a whole number from 0 to " +
                                                   std::to_string(std::numeric_limits<std::uint64_t>::max()) +
                                                   ", got '" + text + "'");
            }
            seed = *v;
          },
          help)
      ->default_str(std::to_string(seed))
      ->type_name("UINT64");
}

CLI::Option* add_threads_option(CLI::App& app, std::optional<int>& threads) {
  return app
      .add_option_function<std::string>(
          "--threads",
          [&threads](const std::string& text) {
            const std::optional<int> v = whole_number<int>(text);
            if (!v || *v < 1 || *v > kMaxThreads) {
              throw CLI::ValidationError("--threads", "must be a whole number in [1, " +
                                                          std::to_string(kMaxThreads) +
                                                          "] (left out: every core), got '" + text + "'");
            }
            threads = *v;
          },
          "Threads, 1 to 1024 (default: every core); results do not depend on it")
      ->type_name("INT");
}

int threads_or_all(const std::optional<int>& threads) {
  return threads ? *threads : std::min(kMaxThreads, omp_get_max_threads());
}

void check_seed_range(const std::string& option, std::uint64_t base, std::int64_t count) {
  if (count < 1) return;
  const auto last = static_cast<std::uint64_t>(count - 1);
  if (base > std::numeric_limits<std::uint64_t>::max() - last) {
    throw sim::ConfigError(option, 0, "",
                           std::to_string(base) + " + " + std::to_string(count) +
                               " seeds would wrap past 18446744073709551615 to 0: give a smaller seed base");
  }
}

}  // namespace swarmpath::app
