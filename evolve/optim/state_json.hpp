// SPDX-License-Identifier: MIT
// JSON pieces shared by the optimisers' state(): exact doubles (nlohmann-json prints 17
// significant digits, so finite values round-trip bit for bit; JSON has no inf or NaN, so
// those are written as strings), the random generator's four words, and a header check.
#pragma once

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>

#include "evolve/optim/optimizer.hpp"
#include "sim/rng.hpp"

namespace swarmpath::evolve {

inline nlohmann::json number_to_json(double v) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  return v;
}

inline double number_from_json(const nlohmann::json& j) {
  if (j.is_string()) {
    const auto s = j.get<std::string>();
    if (s == "inf") return std::numeric_limits<double>::infinity();
    if (s == "-inf") return -std::numeric_limits<double>::infinity();
    if (s == "nan") return std::numeric_limits<double>::quiet_NaN();
    throw std::invalid_argument("optimizer state: '" + s + "' is not a number");
  }
  return j.get<double>();
}

inline nlohmann::json vector_to_json(const Vector& v) {
  auto j = nlohmann::json::array();
  for (const double x : v) j.push_back(number_to_json(x));
  return j;
}

inline Vector vector_from_json(const nlohmann::json& j) {
  Vector v;
  v.reserve(j.size());
  for (const auto& x : j) v.push_back(number_from_json(x));
  return v;
}

inline nlohmann::json vectors_to_json(const std::vector<Vector>& vs) {
  auto j = nlohmann::json::array();
  for (const auto& v : vs) j.push_back(vector_to_json(v));
  return j;
}

inline std::vector<Vector> vectors_from_json(const nlohmann::json& j) {
  std::vector<Vector> vs;
  vs.reserve(j.size());
  for (const auto& v : j) vs.push_back(vector_from_json(v));
  return vs;
}

/// The four xoshiro256** words as unsigned JSON integers (exact in nlohmann-json).
inline nlohmann::json rng_to_json(const sim::Rng& rng) { return rng.state(); }

inline void rng_from_json(const nlohmann::json& j, sim::Rng& rng) { rng.set_state(j.get<sim::Rng::State>()); }

/// Every state starts with the optimiser's name and dimension; restore() checks them.
inline nlohmann::json state_header(const std::string& name, std::size_t dim) {
  return {{"optimizer", name}, {"dim", dim}};
}

inline void check_state_header(const nlohmann::json& state, const std::string& name, std::size_t dim) {
  const auto got = state.at("optimizer").get<std::string>();
  if (got != name) throw std::invalid_argument("optimizer state is for '" + got + "', not '" + name + "'");
  const auto got_dim = state.at("dim").get<std::size_t>();
  if (got_dim != dim) {
    throw std::invalid_argument("optimizer state has dimension " + std::to_string(got_dim) + ", not " +
                                std::to_string(dim));
  }
}

}  // namespace swarmpath::evolve
