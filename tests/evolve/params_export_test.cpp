// SPDX-License-Identifier: MIT
// Exports of a params set: TOML round-trips through load_params, JSON lists every value with
// its unit, the ARGoS block carries every parameter under its SPEC name.
#include "evolve/params_export.hpp"

#include <sstream>

#include <gtest/gtest.h>

#include "evolve/genome.hpp"
#include "sim/rng.hpp"

namespace swarmpath::evolve {
namespace {

// a valid parameter set far from the paper's defaults
sim::Params unusual_params() {
  Genome g;
  for (const sim::ParamInfo& info : sim::param_table()) g.genes.push_back(default_gene(info));
  sim::Rng rng(9);
  for (;;) {
    Vector x(g.dim());
    for (double& xi : x) xi = rng.uniform();
    const Decoded d = decode(g, x);
    if (d.violation.empty()) return d.params;
  }
}

TEST(ParamsExport, JsonHasEveryValueWithItsUnit) {
  const sim::Params p = unusual_params();
  const nlohmann::ordered_json j = params_export_json(p);
  ASSERT_EQ(j.size(), sim::param_table().size());
  for (const sim::ParamInfo& info : sim::param_table()) {
    const auto& e = j.at(std::string(info.name));
    EXPECT_EQ(e.at("unit").get<std::string>(), info.unit);
    switch (info.type) {
      case sim::ParamType::kBool:
        EXPECT_EQ(e.at("value").get<bool>(), sim::get_value(p, info) != 0.0) << info.name;
        break;
      case sim::ParamType::kChoice:
        EXPECT_EQ(e.at("value").get<std::string>(), info.choices[sim::get_value(p, info) != 0.0 ? 1 : 0]);
        break;
      case sim::ParamType::kInteger:
      case sim::ParamType::kReal:
        EXPECT_EQ(e.at("value").get<double>(), sim::get_value(p, info)) << info.name;
        break;
    }
  }
  EXPECT_EQ(j.at("R_vis").at("unit"), "cm");
  // name -> value only, for run.json
  EXPECT_EQ(params_values_json(p).at("v_max").get<double>(), p.v_max);
}

TEST(ParamsExport, ArgosBlockCarriesEveryParameter) {
  const sim::Params p = unusual_params();
  std::ostringstream out;
  write_argos_params(out, p, "test");
  const std::string text = out.str();
  EXPECT_EQ(text.find("<params"), text.find('<', text.find("-->")));  // the element follows the comment
  EXPECT_NE(text.find(" />"), std::string::npos);
  for (const sim::ParamInfo& info : sim::param_table()) {
    std::string v = sim::format_value(p, info);
    if (info.type == sim::ParamType::kChoice) v = info.choices[sim::get_value(p, info) != 0.0 ? 1 : 0];
    const std::string attr = "\n    " + std::string(info.name) + "=\"" + v + "\"";
    EXPECT_NE(text.find(attr), std::string::npos) << attr;
  }
  EXPECT_NE(
      text.find("t_source=\"" + std::string(p.t_source == sim::TSource::kBudget ? "budget" : "elapsed")),
      std::string::npos);
}

TEST(ParamsExport, TomlRoundTripsToIdenticalValues) {
  const sim::Params p = unusual_params();
  std::ostringstream out;
  sim::write_params_toml(out, p, "# test\n");
  const sim::Params back = sim::parse_params(out.str(), "export.toml");
  for (const sim::ParamInfo& info : sim::param_table()) {
    EXPECT_EQ(sim::get_value(back, info), sim::get_value(p, info)) << info.name;
  }
}

}  // namespace
}  // namespace swarmpath::evolve
