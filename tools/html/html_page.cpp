#include "html_page.hpp"

#include <fstream>

#include "html_assets.hpp"
#include "plascap/input_error.hpp"

namespace plascap::html {
namespace {

// Text placed in HTML element content: &, < and > escaped.
std::string escaped(std::string_view text) {
    std::string out;
    for (char c : text) {
        if (c == '&') out += "&amp;";
        else if (c == '<') out += "&lt;";
        else if (c == '>') out += "&gt;";
        else out += c;
    }
    return out;
}

void script(std::string& out, std::string_view code) {
    out += "<script>\n";
    out += code;
    out += "\n</script>\n";
}

}  // namespace

std::string script_safe_json(const std::string& text) {
    std::string out;
    out.reserve(text.size());
    for (std::size_t i = 0; i < text.size(); ++i) {
        out += text[i];
        if (text[i] == '<' && i + 1 < text.size() && text[i + 1] == '/') out += '\\';
    }
    return out;
}

std::string page_text(const Page& page) {
    std::string out = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n";
    out += "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n";
    out += "<meta name=\"generator\" content=\"plascap\">\n";
    out += "<title>" + escaped(page.title) + "</title>\n<style>\n";
    out += assets::page_css();
    out += "\n</style>\n</head>\n<body>\n";
    // The page's own report of its state, for people (a message) and for tests (data-* attributes).
    out += "<div id=\"plascap-status\" data-state=\"loading\" data-errors=\"0\">Loading…</div>\n";
    out += "<script type=\"application/json\" id=\"plascap-data\">";
    out += script_safe_json(page.data);
    out += "</script>\n";
    if (page.kind == PageKind::Replay) {
        script(out, assets::three_js());
        script(out, assets::orbit_controls_js());
    }
    script(out, assets::chart_js());
    script(out, assets::common_js());
    script(out, page.kind == PageKind::Replay ? assets::replay_js() : assets::section_js());
    out += "</body>\n</html>\n";
    return out;
}

void write_page(const std::string& path, const Page& page, const std::string& option) {
    std::ofstream file(path, std::ios::binary);
    if (!file) throw InputError(option + " " + path + ": cannot be written");
    const std::string text = page_text(page);
    file.write(text.data(), static_cast<std::streamsize>(text.size()));
    if (!file.flush()) throw InputError(option + " " + path + ": writing failed");
}

}  // namespace plascap::html
