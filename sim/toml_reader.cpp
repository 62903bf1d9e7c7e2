// SPDX-License-Identifier: MIT
#include "toml_reader.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <toml++/toml.h>

#include "edit_distance.hpp"

namespace swarmpath::sim {

namespace {

int line_of_node(const toml::node& n) { return static_cast<int>(n.source().begin.line); }

std::string type_name(const toml::node& n) {
  switch (n.type()) {
    case toml::node_type::string:
      return "a string";
    case toml::node_type::integer:
      return "an integer";
    case toml::node_type::floating_point:
      return "a number";
    case toml::node_type::boolean:
      return "a boolean";
    case toml::node_type::array:
      return "an array";
    case toml::node_type::table:
      return "a table";
    case toml::node_type::date:
    case toml::node_type::time:
    case toml::node_type::date_time:
      return "a date/time";
    case toml::node_type::none:
      break;
  }
  return "nothing";
}

}  // namespace

TomlDoc::TomlDoc(std::unique_ptr<toml::table> root, std::string name)
    : root_(std::move(root)), name_(std::move(name)) {}

TomlDoc::TomlDoc(TomlDoc&&) noexcept = default;
TomlDoc& TomlDoc::operator=(TomlDoc&&) noexcept = default;
TomlDoc::~TomlDoc() = default;

TomlDoc TomlDoc::parse_file(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw ConfigError(path, 0, "", "is a folder, not a file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ConfigError(path, 0, "", "cannot open file");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw ConfigError(path, 0, "", "cannot read the file");
  return parse_string(text.str(), path);
}

TomlDoc TomlDoc::parse_string(std::string_view text, std::string name) {
  try {
    auto table = std::make_unique<toml::table>(toml::parse(text, name));
    return TomlDoc(std::move(table), std::move(name));
  } catch (const toml::parse_error& e) {
    throw ConfigError(name, static_cast<int>(e.source().begin.line), "",
                      "TOML syntax error: " + std::string(e.description()));
  }
}

TableReader::TableReader(const TomlDoc& doc, const toml::table& table, std::string prefix)
    : doc_(&doc), table_(&table), prefix_(std::move(prefix)) {}

std::string TableReader::path(std::string_view key) const {
  if (prefix_.empty()) return std::string(key);
  return prefix_ + "." + std::string(key);
}

const toml::node* TableReader::get(std::string_view key) const {
  if (std::find(seen_.begin(), seen_.end(), key) == seen_.end()) seen_.emplace_back(key);
  return table_->get(key);
}

bool TableReader::has(std::string_view key) const { return table_->get(key) != nullptr; }

int TableReader::line_of(std::string_view key) const {
  for (auto&& [k, v] : *table_) {
    if (k.str() == key) return static_cast<int>(k.source().begin.line);
  }
  return static_cast<int>(table_->source().begin.line);
}

void TableReader::fail(std::string_view key, const std::string& message) const {
  throw ConfigError(doc_->name(), line_of(key), path(key), message);
}

const toml::node& TableReader::require(std::string_view key) const {
  const toml::node* n = get(key);
  if (n == nullptr) {
    // a misspelling of the key reads better as "unknown key, did you mean" at the typo's line
    for (auto&& [k, v] : *table_) {
      if (edit_distance(k.str(), key) <= 2 && std::find(seen_.begin(), seen_.end(), k.str()) == seen_.end()) {
        throw ConfigError(doc_->name(), static_cast<int>(k.source().begin.line), path(k.str()),
                          "unknown key (did you mean '" + std::string(key) + "'?)");
      }
    }
    const std::string where = prefix_.empty() ? "the top level" : "[" + prefix_ + "]";
    throw ConfigError(doc_->name(), static_cast<int>(table_->source().begin.line), path(key),
                      "missing required key in " + where);
  }
  return *n;
}

double TableReader::as_number(std::string_view key, const toml::node& n) const {
  double v = 0.0;
  if (const auto* i = n.as_integer()) {
    v = static_cast<double>(i->get());
  } else if (const auto* f = n.as_floating_point()) {
    v = f->get();
  } else {
    throw ConfigError(doc_->name(), line_of_node(n), path(key), "expected a number, got " + type_name(n));
  }
  if (!std::isfinite(v)) throw ConfigError(doc_->name(), line_of_node(n), path(key), "must be finite");
  return v;
}

double TableReader::number(std::string_view key) const { return as_number(key, require(key)); }

double TableReader::number_or(std::string_view key, double fallback) const {
  const toml::node* n = get(key);
  return n ? as_number(key, *n) : fallback;
}

std::int64_t TableReader::integer(std::string_view key) const {
  const toml::node& n = require(key);
  if (const auto* i = n.as_integer()) return i->get();
  if (const auto* f = n.as_floating_point()) {
    const double v = f->get();
    if (std::isfinite(v) && v == std::floor(v) && std::fabs(v) < 9.0e15) return static_cast<std::int64_t>(v);
  }
  throw ConfigError(doc_->name(), line_of_node(n), path(key), "expected an integer, got " + type_name(n));
}

std::int64_t TableReader::integer_or(std::string_view key, std::int64_t fallback) const {
  return has(key) ? integer(key) : (get(key), fallback);
}

bool TableReader::boolean(std::string_view key) const {
  const toml::node& n = require(key);
  if (const auto* b = n.as_boolean()) return b->get();
  throw ConfigError(doc_->name(), line_of_node(n), path(key),
                    "expected a boolean (true/false), got " + type_name(n));
}

bool TableReader::boolean_or(std::string_view key, bool fallback) const {
  return has(key) ? boolean(key) : (get(key), fallback);
}

std::string TableReader::string(std::string_view key) const {
  const toml::node& n = require(key);
  if (const auto* s = n.as_string()) return checked_text(key, n, s->get());
  throw ConfigError(doc_->name(), line_of_node(n), path(key), "expected a string, got " + type_name(n));
}

std::string TableReader::checked_text(std::string_view key, const toml::node& n,
                                      const std::string& text) const {
  // names and paths end up in SVG, XML, CSV and terminals, where control characters break them
  for (const char ch : text) {
    const auto c = static_cast<unsigned char>(ch);
    if (c < 0x20 || c == 0x7f) {
      char code[8];
      std::snprintf(code, sizeof code, "U+%04X", c);
      throw ConfigError(doc_->name(), line_of_node(n), path(key),
                        std::string("contains the control character ") + code +
                            " (names and paths may not hold control characters)");
    }
  }
  return text;
}

std::string TableReader::string_or(std::string_view key, std::string fallback) const {
  return has(key) ? string(key) : (get(key), std::move(fallback));
}

Vec2 TableReader::vec2(std::string_view key) const {
  const toml::node& n = require(key);
  const auto* arr = n.as_array();
  if (arr == nullptr || arr->size() != 2) {
    throw ConfigError(doc_->name(), line_of_node(n), path(key),
                      "expected a pair of numbers such as [1.0, 2.0], got " +
                          (arr ? "an array of " + std::to_string(arr->size()) : type_name(n)));
  }
  return {as_number(key, *arr->get(0)), as_number(key, *arr->get(1))};
}

Vec2 TableReader::vec2_or(std::string_view key, Vec2 fallback) const {
  return has(key) ? vec2(key) : (get(key), fallback);
}

std::vector<double> TableReader::numbers(std::string_view key) const {
  const toml::node& n = require(key);
  const auto* arr = n.as_array();
  if (arr == nullptr) {
    throw ConfigError(doc_->name(), line_of_node(n), path(key),
                      "expected an array of numbers, got " + type_name(n));
  }
  std::vector<double> out;
  for (const auto& e : *arr) out.push_back(as_number(key, e));
  return out;
}

std::vector<std::string> TableReader::strings(std::string_view key) const {
  const toml::node& n = require(key);
  const auto* arr = n.as_array();
  if (arr == nullptr) {
    throw ConfigError(doc_->name(), line_of_node(n), path(key),
                      "expected an array of strings, got " + type_name(n));
  }
  std::vector<std::string> out;
  for (const auto& e : *arr) {
    const auto* s = e.as_string();
    if (s == nullptr) {
      throw ConfigError(doc_->name(), line_of_node(e), path(key), "expected a string, got " + type_name(e));
    }
    out.push_back(checked_text(key, e, s->get()));
  }
  return out;
}

std::optional<TableReader> TableReader::table(std::string_view key) const {
  const toml::node* n = get(key);
  if (n == nullptr) return std::nullopt;
  const auto* t = n->as_table();
  if (t == nullptr) {
    throw ConfigError(doc_->name(), line_of_node(*n), path(key), "expected a table, got " + type_name(*n));
  }
  return TableReader(*doc_, *t, path(key));
}

TableReader TableReader::required_table(std::string_view key) const {
  const toml::node& n = require(key);
  const auto* t = n.as_table();
  if (t == nullptr) {
    throw ConfigError(doc_->name(), line_of_node(n), path(key), "expected a table, got " + type_name(n));
  }
  return TableReader(*doc_, *t, path(key));
}

std::vector<TableReader> TableReader::table_array(std::string_view key) const {
  std::vector<TableReader> out;
  const toml::node* n = get(key);
  if (n == nullptr) return out;
  const auto* arr = n->as_array();
  if (arr == nullptr) {
    throw ConfigError(doc_->name(), line_of_node(*n), path(key),
                      "expected an array of tables ([[" + std::string(key) + "]]), got " + type_name(*n));
  }
  for (std::size_t i = 0; i < arr->size(); ++i) {
    const toml::node& e = *arr->get(i);
    const auto* t = e.as_table();
    const std::string name = path(key) + "[" + std::to_string(i) + "]";
    if (t == nullptr) {
      throw ConfigError(doc_->name(), line_of_node(e), name, "expected a table, got " + type_name(e));
    }
    out.emplace_back(*doc_, *t, name);
  }
  return out;
}

std::vector<std::string> TableReader::keys() const {
  std::vector<std::string> out;
  for (auto&& [k, v] : *table_) out.emplace_back(k.str());
  return out;
}

void TableReader::finish() const {
  for (auto&& [k, v] : *table_) {
    if (std::find(seen_.begin(), seen_.end(), k.str()) != seen_.end()) continue;
    std::string message = "unknown key";
    std::size_t best = 3;
    for (const std::string& known : seen_) {
      const std::size_t d = edit_distance(k.str(), known);
      if (d < best) {
        best = d;
        message = "unknown key (did you mean '" + known + "'?)";
      }
    }
    throw ConfigError(doc_->name(), static_cast<int>(k.source().begin.line), path(k.str()), message);
  }
}

}  // namespace swarmpath::sim
