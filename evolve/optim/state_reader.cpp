// SPDX-License-Identifier: MIT
#include "evolve/optim/state_reader.hpp"

#include <charconv>
#include <cmath>

namespace swarmpath::evolve {

namespace {

std::string kind(const nlohmann::json& v) {
  switch (v.type()) {
    case nlohmann::json::value_t::null:
      return "null";
    case nlohmann::json::value_t::boolean:
      return "a boolean";
    case nlohmann::json::value_t::string:
      return "a string";
    case nlohmann::json::value_t::array:
      return "an array";
    case nlohmann::json::value_t::object:
      return "an object";
    case nlohmann::json::value_t::number_float:
      return "the number " + number_text(v.get<double>());
    case nlohmann::json::value_t::number_integer:
    case nlohmann::json::value_t::number_unsigned:
      return "the integer " + v.dump();
    default:
      return "something else";
  }
}

// "[0, 1]"; "(0, inf)" for the positive numbers (lo = the smallest normal double)
std::string range_text(double lo, double hi) {
  const auto end = [](double v) {
    return std::isinf(v) ? std::string(v > 0 ? "inf" : "-inf") : number_text(v);
  };
  const bool positive = lo == std::numeric_limits<double>::min();
  return (positive ? "(0" : "[" + end(lo)) + ", " + end(hi) + (std::isinf(hi) ? ")" : "]");
}

void check_length(const std::string& field, const nlohmann::json& v, std::size_t count, const char* what) {
  if (!v.is_array())
    throw StateError(field, std::string("expected an array of ") + what + ", got " + kind(v));
  if (count != StateReader::kAny && v.size() != count) {
    throw StateError(field,
                     "expected " + std::to_string(count) + " " + what + ", got " + std::to_string(v.size()));
  }
}

}  // namespace

std::string number_text(double v) {
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

StateReader::StateReader(const nlohmann::json& j, std::string path) : j_(j), path_(std::move(path)) {
  if (!j_.is_object())
    throw StateError(path_.empty() ? "(the file)" : path_, "expected an object, got " + kind(j_));
}

std::string StateReader::field(std::string_view key) const {
  return path_.empty() ? std::string(key) : path_ + "." + std::string(key);
}

void StateReader::fail(std::string_view key, const std::string& message) const {
  throw StateError(field(key), message);
}

const nlohmann::json& StateReader::at(std::string_view key) const {
  const auto it = j_.find(key);
  if (it == j_.end()) fail(key, "missing");
  return *it;
}

StateReader StateReader::object(std::string_view key) const { return StateReader(at(key), field(key)); }

std::vector<StateReader> StateReader::objects(std::string_view key, std::size_t count) const {
  const nlohmann::json& v = at(key);
  check_length(field(key), v, count, "objects");
  std::vector<StateReader> out;
  out.reserve(v.size());
  for (std::size_t i = 0; i < v.size(); ++i)
    out.emplace_back(v[i], field(key) + "[" + std::to_string(i) + "]");
  return out;
}

std::int64_t StateReader::integer(std::string_view key, std::int64_t lo, std::int64_t hi) const {
  const nlohmann::json& v = at(key);
  const std::string range = "must lie in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], got ";
  if (v.is_number_unsigned()) {
    const auto u = v.get<std::uint64_t>();
    if (u > static_cast<std::uint64_t>(std::max<std::int64_t>(hi, 0)) || static_cast<std::int64_t>(u) < lo)
      fail(key, range + v.dump());
    return static_cast<std::int64_t>(u);
  }
  if (!v.is_number_integer()) fail(key, "expected an integer, got " + kind(v));
  const auto x = v.get<std::int64_t>();
  if (x < lo || x > hi) fail(key, range + std::to_string(x));
  return x;
}

std::uint64_t StateReader::word(std::string_view key) const {
  const nlohmann::json& v = at(key);
  if (!v.is_number_unsigned()) fail(key, "expected an unsigned integer, got " + kind(v));
  return v.get<std::uint64_t>();
}

double StateReader::number(std::string_view key, double lo, double hi) const {
  return numbers_of(field(key), nlohmann::json::array({at(key)}), 1, lo, hi, false)[0];
}

double StateReader::number_or_null(std::string_view key, double lo, double hi) const {
  if (at(key).is_null()) return std::numeric_limits<double>::quiet_NaN();
  return number(key, lo, hi);
}

double StateReader::extended(std::string_view key, double lo, double hi) const {
  return numbers_of(field(key), nlohmann::json::array({at(key)}), 1, lo, hi, true)[0];
}

bool StateReader::boolean(std::string_view key) const {
  const nlohmann::json& v = at(key);
  if (!v.is_boolean()) fail(key, "expected true or false, got " + kind(v));
  return v.get<bool>();
}

std::string StateReader::text(std::string_view key) const {
  const nlohmann::json& v = at(key);
  if (!v.is_string()) fail(key, "expected a string, got " + kind(v));
  return v.get<std::string>();
}

Vector StateReader::numbers(std::string_view key, std::size_t count, double lo, double hi,
                            bool extended) const {
  return numbers_of(field(key), at(key), count, lo, hi, extended);
}

std::vector<Vector> StateReader::vectors(std::string_view key, std::size_t count, std::size_t length,
                                         double lo, double hi, bool extended) const {
  const nlohmann::json& v = at(key);
  check_length(field(key), v, count, "vectors");
  std::vector<Vector> out;
  out.reserve(v.size());
  for (std::size_t i = 0; i < v.size(); ++i) {
    out.push_back(numbers_of(field(key) + "[" + std::to_string(i) + "]", v[i], length, lo, hi, extended));
  }
  return out;
}

Vector StateReader::point(std::string_view key, const Bounds& b) const {
  return point_of(field(key), at(key), b);
}

std::vector<Vector> StateReader::points(std::string_view key, std::size_t count, const Bounds& b) const {
  const nlohmann::json& v = at(key);
  check_length(field(key), v, count, "points");
  std::vector<Vector> out;
  out.reserve(v.size());
  for (std::size_t i = 0; i < v.size(); ++i)
    out.push_back(point_of(field(key) + "[" + std::to_string(i) + "]", v[i], b));
  return out;
}

std::vector<bool> StateReader::booleans(std::string_view key, std::size_t count) const {
  const nlohmann::json& v = at(key);
  check_length(field(key), v, count, "booleans");
  std::vector<bool> out;
  for (const nlohmann::json& b : v) {
    if (!b.is_boolean()) fail(key, "expected true or false, got " + kind(b));
    out.push_back(b.get<bool>());
  }
  return out;
}

sim::Rng::State StateReader::rng(std::string_view key) const {
  const nlohmann::json& v = at(key);
  sim::Rng::State s{};
  check_length(field(key), v, s.size(), "unsigned integers");
  bool zero = true;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (!v[i].is_number_unsigned()) fail(key, "expected unsigned integers, got " + kind(v[i]));
    s[i] = v[i].get<std::uint64_t>();
    zero = zero && s[i] == 0;
  }
  if (zero) fail(key, "a random generator's words are never all zero");
  return s;
}

void StateReader::header(const std::string& name, std::size_t dim) const {
  const std::string got = text("optimizer");
  if (got != name) fail("optimizer", "the state is for '" + got + "', not '" + name + "'");
  const std::int64_t d = integer("dim", 1, std::numeric_limits<std::int32_t>::max());
  if (static_cast<std::size_t>(d) != dim) {
    fail("dim", "the state has dimension " + std::to_string(d) + ", the problem " + std::to_string(dim));
  }
}

Vector StateReader::point_of(const std::string& field, const nlohmann::json& v, const Bounds& b) const {
  Vector x = numbers_of(field, v, b.dim(), -kInf, kInf, false);
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (!(x[i] >= b.lower[i] && x[i] <= b.upper[i])) {
      throw StateError(field, "value " + std::to_string(i) + " must lie in " +
                                  range_text(b.lower[i], b.upper[i]) + ", got " + number_text(x[i]));
    }
  }
  return x;
}

Vector StateReader::numbers_of(const std::string& field, const nlohmann::json& v, std::size_t count,
                               double lo, double hi, bool extended) const {
  check_length(field, v, count, "numbers");
  Vector out;
  out.reserve(v.size());
  for (std::size_t i = 0; i < v.size(); ++i) {
    const nlohmann::json& e = v[i];
    double x = 0.0;
    if (e.is_number()) {
      x = e.get<double>();
    } else if (extended && e.is_string() && (e == "inf" || e == "-inf" || e == "nan")) {
      x = e == "nan" ? std::numeric_limits<double>::quiet_NaN() : (e == "inf" ? kInf : -kInf);
    } else {
      throw StateError(field, "expected a number, got " + kind(e));
    }
    if (!std::isnan(x) && (x < lo || x > hi)) {
      throw StateError(field, (v.size() > 1 ? "value " + std::to_string(i) + " " : std::string()) +
                                  "must lie in " + range_text(lo, hi) + ", got " + number_text(x));
    }
    out.push_back(x);
  }
  return out;
}

}  // namespace swarmpath::evolve
