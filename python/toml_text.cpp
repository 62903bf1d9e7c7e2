// SPDX-License-Identifier: MIT
// Python values as TOML text, so that dicts and keyword arguments go through the very parsers
// (and checks and messages) that files go through.
#include <cstdio>
#include <string>

#include "bindings.hpp"
#include "sim/config_error.hpp"

namespace swarmpath::python {

namespace {

std::string toml_key(const std::string& k) {
  bool bare = !k.empty();
  for (const char ch : k) {
    const bool ok = (ch >= 'A' && ch <= 'Z') || (ch >= 'a' && ch <= 'z') || (ch >= '0' && ch <= '9') ||
                    ch == '_' || ch == '-';
    bare = bare && ok;
  }
  if (bare) return k;
  std::string out = "\"";
  for (const char ch : k) out += (ch == '"' || ch == '\\') ? std::string("\\") + ch : std::string(1, ch);
  return out + "\"";
}

std::string toml_string(const std::string& s) {
  std::string out = "\"";
  for (const char ch : s) {
    switch (ch) {
      case '"':
        out += "\\\"";
        break;
      case '\\':
        out += "\\\\";
        break;
      case '\n':
        out += "\\n";
        break;
      case '\t':
        out += "\\t";
        break;
      default:
        if (static_cast<unsigned char>(ch) < 0x20) {
          char buf[8];
          std::snprintf(buf, sizeof buf, "\\u%04x", static_cast<unsigned>(static_cast<unsigned char>(ch)));
          out += buf;
        } else {
          out += ch;
        }
    }
  }
  return out + "\"";
}

std::string toml_value(py::handle v, const std::string& name, int line, const std::string& key) {
  if (py::isinstance<py::bool_>(v)) return v.cast<bool>() ? "true" : "false";
  if (py::isinstance<py::str>(v)) return toml_string(v.cast<std::string>());
  if (py::isinstance<py::dict>(v)) {
    std::string out = "{";
    bool first = true;
    for (const auto& [k, x] : v.cast<py::dict>()) {
      const std::string ks = py::str(k);
      out += (first ? " " : ", ") + toml_key(ks) + " = " + toml_value(x, name, line, key + "." + ks);
      first = false;
    }
    return out + (first ? "}" : " }");
  }
  if (py::isinstance<py::list>(v) || py::isinstance<py::tuple>(v)) {
    std::string out = "[";
    bool first = true;
    for (const py::handle x : v) {
      out += (first ? "" : ", ") + toml_value(x, name, line, key);
      first = false;
    }
    return out + "]";
  }
  const py::object o = py::reinterpret_borrow<py::object>(v);
  if (py::isinstance<py::int_>(v) || py::hasattr(v, "__index__")) return py::str(py::int_(o));
  // Python writes a float with a '.' or an exponent, and inf and nan, as TOML does
  if (py::isinstance<py::float_>(v) || py::hasattr(v, "__float__")) return py::repr(py::float_(o));
  throw sim::ConfigError(name, line, key,
                         "a value of type " + std::string(py::str(v.get_type().attr("__name__"))) +
                             " has no TOML form (give a bool, number, string, list or dict)");
}

}  // namespace

std::string toml_text(const py::dict& d, const std::string& name) {
  std::string out;
  int line = 0;
  for (const auto& [k, v] : d) {
    ++line;
    const std::string key = py::str(k);
    out += toml_key(key) + " = " + toml_value(v, name, line, key) + "\n";
  }
  return out;
}

}  // namespace swarmpath::python
