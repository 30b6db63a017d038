#pragma once
// A figure's markup in a self-contained page: its JSON (figure_data.hpp) in a
// <script type="application/json"> that the embedded figures.js draws with the embedded uPlot.

#include <nlohmann/json.hpp>
#include <string>

namespace hilrig::rig {

// <figure class="evidence" data-kind=...> holding the figure's data and its caption (HTML);
// empty for a null figure.
[[nodiscard]] std::string figure_html(const nlohmann::json& figure, const std::string& caption);

// For the page's <head>: uPlot's stylesheet and the figures' own.
[[nodiscard]] std::string figure_styles();
// For the end of the page's <body>: uPlot and figures.js, which draw every figure above.
[[nodiscard]] std::string figure_scripts();

} // namespace hilrig::rig
