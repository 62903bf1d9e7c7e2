// SPDX-License-Identifier: MIT
// Strict, line-aware reading of TOML tables: every value is type-checked, every error names
// file:line and the dotted key, and keys nobody asked for are rejected as unknown.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "config_error.hpp"
#include "vec2.hpp"

namespace toml {
inline namespace v3 {
class table;
class node;
}  // namespace v3
}  // namespace toml

namespace swarmpath::sim {

/// A parsed TOML document that remembers its file name for error messages.
class TomlDoc {
 public:
  /// Reads and parses `path`; throws ConfigError when the file cannot be read or is not TOML.
  static TomlDoc parse_file(const std::string& path);
  /// Parses `text`; `name` stands for the file in messages.
  static TomlDoc parse_string(std::string_view text, std::string name);

  TomlDoc(TomlDoc&&) noexcept;
  TomlDoc& operator=(TomlDoc&&) noexcept;
  ~TomlDoc();

  const toml::table& root() const { return *root_; }

  const std::string& name() const { return name_; }

 private:
  TomlDoc(std::unique_ptr<toml::table> root, std::string name);
  std::unique_ptr<toml::table> root_;
  std::string name_;
};

/// Reads the keys of one table. Call finish() after the last read: it rejects unknown keys.
class TableReader {
 public:
  TableReader(const TomlDoc& doc, const toml::table& table, std::string prefix);

  bool has(std::string_view key) const;

  /// Marks `key` as known without reading it (finish() will not call it unknown).
  void allow(std::string_view key) const { (void)get(key); }

  double number(std::string_view key) const;
  double number_or(std::string_view key, double fallback) const;
  std::int64_t integer(std::string_view key) const;
  std::int64_t integer_or(std::string_view key, std::int64_t fallback) const;
  bool boolean(std::string_view key) const;
  bool boolean_or(std::string_view key, bool fallback) const;
  std::string string(std::string_view key) const;
  std::string string_or(std::string_view key, std::string fallback) const;
  /// A two-number array such as `center = [1.0, -2.5]`.
  Vec2 vec2(std::string_view key) const;
  Vec2 vec2_or(std::string_view key, Vec2 fallback) const;
  /// A list of numbers, e.g. `robots = [60, 70, 80]`.
  std::vector<double> numbers(std::string_view key) const;
  std::vector<std::string> strings(std::string_view key) const;

  /// A sub-table (`[name]` or inline); nullopt when absent.
  std::optional<TableReader> table(std::string_view key) const;
  TableReader required_table(std::string_view key) const;
  /// An array of tables (`[[name]]`); empty when absent.
  std::vector<TableReader> table_array(std::string_view key) const;

  /// Throws ConfigError for the first key (in file order) that no read above touched.
  void finish() const;

  /// Throws ConfigError at `key`'s line (the table's line when the key is absent).
  [[noreturn]] void fail(std::string_view key, const std::string& message) const;

  /// The dotted name of `key` inside this table, e.g. "cylinder[2].radius".
  std::string path(std::string_view key) const;

  int line_of(std::string_view key) const;

  const std::string& file() const { return doc_->name(); }

  const std::string& prefix() const { return prefix_; }

  /// All keys of this table, in file order (for tables whose keys are data, such as params).
  std::vector<std::string> keys() const;

 private:
  const toml::node* get(std::string_view key) const;
  const toml::node& require(std::string_view key) const;
  double as_number(std::string_view key, const toml::node& n) const;
  std::string checked_text(std::string_view key, const toml::node& n, const std::string& text) const;

  const TomlDoc* doc_;
  const toml::table* table_;
  std::string prefix_;
  mutable std::vector<std::string> seen_;
};

}  // namespace swarmpath::sim
