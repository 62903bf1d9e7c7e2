// SPDX-License-Identifier: MIT
#include "params_export.hpp"

#include <ostream>
#include <string>

#include "sim/additions.hpp"
#include "xml_escape.hpp"

namespace swarmpath::evolve {

namespace {}  // namespace

nlohmann::ordered_json param_value_json(const sim::Params& p, const sim::ParamInfo& info) {
  const double v = sim::get_value(p, info);
  switch (info.type) {
    case sim::ParamType::kBool:
      return v != 0.0;
    case sim::ParamType::kChoice:
      return std::string(info.choices[v != 0.0 ? 1 : 0]);
    case sim::ParamType::kInteger:
      return static_cast<std::int64_t>(v);
    case sim::ParamType::kReal:
      break;
  }
  return v;
}

nlohmann::ordered_json params_values_json(const sim::Params& p) {
  nlohmann::ordered_json j = nlohmann::ordered_json::object();
  for (const sim::ParamInfo& info : sim::param_table()) j[std::string(info.name)] = param_value_json(p, info);
  return j;
}

nlohmann::ordered_json controller_json(const sim::Params& p) {
  nlohmann::ordered_json off = nlohmann::ordered_json::array();
  for (const sim::Addition& a : sim::additions()) {
    if (!sim::is_on(p, a)) off.push_back(std::string(a.name));
  }
  nlohmann::ordered_json j;
  j["name"] = std::string(sim::controller_name(p));
  j["additions_on"] = sim::additions_on(p);
  j["additions"] = sim::additions().size();
  j["additions_off"] = std::move(off);
  return j;
}

std::string controller_text(const sim::Params& p) {
  return std::string(sim::controller_name(p)) + " controller (" + std::to_string(sim::additions_on(p)) +
         " of " + std::to_string(sim::additions().size()) + " additions beyond SPEC on)";
}

nlohmann::ordered_json params_export_json(const sim::Params& p) {
  nlohmann::ordered_json j = nlohmann::ordered_json::object();
  for (const sim::ParamInfo& info : sim::param_table()) {
    nlohmann::ordered_json e;
    e["value"] = param_value_json(p, info);
    e["unit"] = std::string(info.unit);
    e["row"] = info.row;
    e["meaning"] = std::string(info.meaning);
    j[std::string(info.name)] = std::move(e);
  }
  return j;
}

void write_argos_params(std::ostream& out, const sim::Params& p, std::string_view source) {
  out << "<!-- swarmpath controller parameters (SPEC 7 names; units: cm, ticks of 0.1 s, degrees)";
  if (!source.empty()) out << " from " << xml_escape(source);
  out << " -->\n<params";
  for (const sim::ParamInfo& info : sim::param_table()) {
    std::string v = sim::format_value(p, info);
    if (info.type == sim::ParamType::kChoice)
      v = std::string(info.choices[sim::get_value(p, info) != 0.0 ? 1 : 0]);
    out << "\n    " << info.name << "=\"" << xml_escape(v) << "\"";
  }
  out << " />\n";
}

}  // namespace swarmpath::evolve
