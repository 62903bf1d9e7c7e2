// SPDX-License-Identifier: MIT
// Strict reading of a saved state (an optimiser's state(), a checkpoint): every value's type,
// range and length is checked (1.5 is not an integer, -5 not a count, "1" not a number), and
// every error is a StateError that names the field's path ("optimizer.sigma", "elites[0].x"), so
// that a tampered or damaged checkpoint is refused with a clear message instead of resuming into
// nonsense or a crash.
#pragma once

#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "evolve/optim/optimizer.hpp"
#include "sim/rng.hpp"

namespace swarmpath::evolve {

/// A field of a saved state that does not read back: what() is "FIELD: message".
class StateError : public std::invalid_argument {
 public:
  StateError(std::string field, std::string message)
      : std::invalid_argument(field + ": " + message),
        field_(std::move(field)),
        message_(std::move(message)) {}

  /// The field's path inside the state, e.g. "optimizer.sigma" or "elites[0].x".
  const std::string& field() const { return field_; }

  /// What is wrong with it.
  const std::string& message() const { return message_; }

 private:
  std::string field_;
  std::string message_;
};

/// Shortest text that reads back to the same double.
std::string number_text(double v);

/// Reads one JSON object of a saved state; `path` is its own place ("" at the top).
class StateReader {
 public:
  static constexpr std::size_t kAny = std::numeric_limits<std::size_t>::max();
  static constexpr double kInf = std::numeric_limits<double>::infinity();

  StateReader(const nlohmann::json& j, std::string path);

  /// The path of `key` in this object, e.g. "optimizer.sigma".
  std::string field(std::string_view key) const;

  [[noreturn]] void fail(std::string_view key, const std::string& message) const;

  bool has(std::string_view key) const { return j_.contains(key); }

  /// The raw value (StateError when missing).
  const nlohmann::json& at(std::string_view key) const;

  StateReader object(std::string_view key) const;

  /// The objects of an array: exactly `count` of them, or any number with kAny.
  std::vector<StateReader> objects(std::string_view key, std::size_t count = kAny) const;

  /// An integer in [lo, hi].
  std::int64_t integer(std::string_view key, std::int64_t lo, std::int64_t hi) const;

  /// Any unsigned 64-bit integer (a seed).
  std::uint64_t word(std::string_view key) const;

  /// A finite number in [lo, hi].
  double number(std::string_view key, double lo, double hi) const;

  /// A finite number in [lo, hi], or null (read as NaN).
  double number_or_null(std::string_view key, double lo, double hi) const;

  /// A number as number_to_json writes it: in [lo, hi], or "inf", "-inf", "nan" where [lo, hi]
  /// allows them (NaN always).
  double extended(std::string_view key, double lo, double hi) const;

  bool boolean(std::string_view key) const;

  std::string text(std::string_view key) const;

  /// `count` numbers (kAny: any number) in [lo, hi]; with `extended`, in number_to_json's form.
  Vector numbers(std::string_view key, std::size_t count, double lo, double hi, bool extended = false) const;

  /// `count` vectors (kAny: any number) of `length` numbers each, in [lo, hi]; an error in vector
  /// i names "key[i]".
  std::vector<Vector> vectors(std::string_view key, std::size_t count, std::size_t length, double lo,
                              double hi, bool extended = false) const;

  /// A point of the box `b` (length b.dim(), every coordinate inside its bounds).
  Vector point(std::string_view key, const Bounds& b) const;

  /// `count` points of the box `b` (kAny: any number); an error in point i names "key[i]".
  std::vector<Vector> points(std::string_view key, std::size_t count, const Bounds& b) const;

  /// `count` booleans.
  std::vector<bool> booleans(std::string_view key, std::size_t count) const;

  /// The four words of a xoshiro256** generator (never all zero).
  sim::Rng::State rng(std::string_view key) const;

  /// The header every optimiser state starts with (state_header): its name and dimension.
  void header(const std::string& name, std::size_t dim) const;

 private:
  Vector point_of(const std::string& field, const nlohmann::json& v, const Bounds& b) const;
  Vector numbers_of(const std::string& field, const nlohmann::json& v, std::size_t count, double lo,
                    double hi, bool extended) const;

  const nlohmann::json& j_;
  std::string path_;
};

}  // namespace swarmpath::evolve
