// SPDX-License-Identifier: MIT
// JSON pieces shared by the optimisers' state(): exact doubles (nlohmann-json prints 17
// significant digits, so finite values round-trip bit for bit; JSON has no inf or NaN, so
// those are written as strings), the random generator's four words, and the header. Reading a state back is
// StateReader's (state_reader.hpp): strict, field by field.
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

inline nlohmann::json vectors_to_json(const std::vector<Vector>& vs) {
  auto j = nlohmann::json::array();
  for (const auto& v : vs) j.push_back(vector_to_json(v));
  return j;
}

/// The four xoshiro256** words as unsigned JSON integers (exact in nlohmann-json).
inline nlohmann::json rng_to_json(const sim::Rng& rng) { return rng.state(); }

inline void rng_from_json(const nlohmann::json& j, sim::Rng& rng) { rng.set_state(j.get<sim::Rng::State>()); }

/// Every state starts with the optimiser's name and dimension; restore() checks them
/// (StateReader::header).
inline nlohmann::json state_header(const std::string& name, std::size_t dim) {
  return {{"optimizer", name}, {"dim", dim}};
}

}  // namespace swarmpath::evolve
