// SPDX-License-Identifier: MIT
// Self-contained HTML pages: web/page.html filled with the embedded styles and scripts (web/, built
// into the binary) and recordings as base64, so that a page opens from disk with no network.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace swarmpath::app {

/// A recording to put in a page: its bytes (.swrec) and the title the viewer shows.
struct PageRecording {
  std::string title;
  std::string bytes;
};

/// RFC 4648 base64.
std::string base64(std::string_view bytes);

/// Text with <, >, & and " as entities.
std::string html_escape(std::string_view text);

/// The viewer's element and the recordings' data elements (what a page's body holds to play them).
std::string viewer_html(const std::vector<PageRecording>& recordings);

/// A whole page: web/page.html with `body`, the viewer's style and script (and `extra_style`).
std::string html_page(const std::string& title, const std::string& body, std::string_view extra_style = {});

/// The viewer's page for these recordings (`swarmpath view`).
std::string viewer_page(const std::string& title, const std::vector<PageRecording>& recordings);

}  // namespace swarmpath::app
