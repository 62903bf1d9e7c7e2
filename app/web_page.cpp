// SPDX-License-Identifier: MIT
#include "web_page.hpp"

#include <stdexcept>

#include "evolve/report.hpp"
#include "evolve/xml_escape.hpp"
#include "web_assets.hpp"

namespace swarmpath::app {

namespace {

// replaces the one occurrence of `key` in `text`
void fill(std::string& text, std::string_view key, std::string_view value) {
  const std::size_t at = text.find(key);
  if (at == std::string::npos) throw std::logic_error("web/page.html has no " + std::string(key));
  text.replace(at, key.size(), value);
}

}  // namespace

std::string base64(std::string_view bytes) {
  static constexpr char kDigits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  std::size_t i = 0;
  const auto at = [&](std::size_t k) { return static_cast<unsigned>(static_cast<unsigned char>(bytes[k])); };
  for (; i + 2 < bytes.size(); i += 3) {
    const unsigned v = (at(i) << 16) | (at(i + 1) << 8) | at(i + 2);
    out += kDigits[(v >> 18) & 63];
    out += kDigits[(v >> 12) & 63];
    out += kDigits[(v >> 6) & 63];
    out += kDigits[v & 63];
  }
  if (i + 1 == bytes.size()) {
    const unsigned v = at(i) << 16;
    out += kDigits[(v >> 18) & 63];
    out += kDigits[(v >> 12) & 63];
    out += "==";
  } else if (i + 2 == bytes.size()) {
    const unsigned v = (at(i) << 16) | (at(i + 1) << 8);
    out += kDigits[(v >> 18) & 63];
    out += kDigits[(v >> 12) & 63];
    out += kDigits[(v >> 6) & 63];
    out += '=';
  }
  return out;
}

std::string html_escape(std::string_view text) { return evolve::xml_escape(text); }

std::string viewer_html(const std::vector<PageRecording>& recordings) {
  std::string out = "<div class=\"swp-viewer\"></div>\n";
  for (const PageRecording& r : recordings) {
    out += "<script type=\"application/x-swrec\" data-title=\"" + html_escape(r.title) + "\">\n";
    const std::string data = base64(r.bytes);
    for (std::size_t i = 0; i < data.size(); i += 120) out.append(data, i, 120).push_back('\n');
    out += "</script>\n";
  }
  return out;
}

std::string html_page(const std::string& title, const std::string& body, std::string_view extra_style) {
  std::string page(web::page_html());
  std::string style(web::viewer_css());
  style += extra_style;
  // fill the page's own placeholders first: the script and body may contain the same words
  const evolve::BuildInfo b = evolve::build_info();
  fill(page, "{{GENERATOR}}", html_escape("swarmpath " + b.version + " (git " + b.git_commit + ")"));
  fill(page, "{{TITLE}}", html_escape(title));
  const std::size_t style_at = page.find("{{STYLE}}");
  const std::size_t body_at = page.find("{{BODY}}");
  const std::size_t script_at = page.find("{{SCRIPT}}");
  if (style_at == std::string::npos || body_at == std::string::npos || script_at == std::string::npos)
    throw std::logic_error("web/page.html lacks a placeholder");
  std::string out = page.substr(0, style_at);
  out += style;
  out.append(page, style_at + 9, body_at - style_at - 9);
  out += body;
  out.append(page, body_at + 8, script_at - body_at - 8);
  out += web::viewer_js();
  out.append(page, script_at + 10);
  return out;
}

std::string viewer_page(const std::string& title, const std::vector<PageRecording>& recordings) {
  return html_page(title, viewer_html(recordings),
                   "html, body { margin: 0; height: 100%; background: #f3f3ef; }\n"
                   "body > .swp-viewer { height: 100vh; }\n");
}

}  // namespace swarmpath::app
