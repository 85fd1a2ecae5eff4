#pragma once
// The files the pages inline, embedded into the tools at build time (tools/html/CMakeLists.txt).
#include <string_view>

namespace plascap::html::assets {

std::string_view three_js();           // Debian libjs-three: three.min.js
std::string_view orbit_controls_js();  // its examples/js/controls/OrbitControls.js
std::string_view chart_js();           // Debian libjs-chart.js: chart.min.js
std::string_view page_css();           // tools/html/page.css
std::string_view common_js();          // tools/html/common.js
std::string_view replay_js();          // tools/html/replay.js
std::string_view section_js();         // tools/html/section.js

}  // namespace plascap::html::assets
