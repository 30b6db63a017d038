#pragma once
// The report's front end, embedded at build time (rig/results/CMakeLists.txt): uPlot from npm
// (report-web/package-lock.json) and figures.js, which draws each figure's JSON with it.

#include <string_view>

namespace hilrig::rig::report_assets {

[[nodiscard]] std::string_view uplot_js();   // uPlot.iife.min.js
[[nodiscard]] std::string_view uplot_css();  // uPlot.min.css
[[nodiscard]] std::string_view figures_js(); // report-web/figures.js

} // namespace hilrig::rig::report_assets
