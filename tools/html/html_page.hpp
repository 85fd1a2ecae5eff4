#pragma once
// One self-contained HTML page (plastic-sim --html, section-calc --html): the page's style, the
// libraries and page code inlined as <script> elements, and the data the page shows as a JSON
// <script> element the page code reads. It opens from disk, with no server and no network.
#include <string>
#include <string_view>
#include <vector>

namespace plascap::html {

enum class PageKind { Replay, Section };

struct Page {
    PageKind kind = PageKind::Replay;
    std::string title;
    std::string data;  // JSON text, read by the page code from document.getElementById("plascap-data")
};

// The page as text: three.js and OrbitControls (replays), Chart.js, page.css and the kind's code.
std::string page_text(const Page& page);

// Writes page_text() to `path`; throws InputError naming `option` and the path when it cannot.
void write_page(const std::string& path, const Page& page, const std::string& option);

// JSON text made safe inside a <script> element: "</" becomes "<\/" (the same string to JSON.parse),
// so no text in the data can close the element.
std::string script_safe_json(const std::string& json);

// `json` as compact text, invalid UTF-8 replaced (names come from users' files).
template <class Json>
std::string json_text(const Json& json) {
    return json.dump(-1, ' ', false, Json::error_handler_t::replace);
}

}  // namespace plascap::html
