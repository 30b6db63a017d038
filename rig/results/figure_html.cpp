#include "rig/results/figure_html.hpp"

#include <fmt/format.h>

#include "rig/results/report_assets.hpp"
#include "rig/results/xml_escape.hpp"

namespace hilrig::rig {
namespace {

// JSON inside <script>: "</" only occurs in its strings, where "<\/" reads the same.
std::string script_safe(std::string text) {
  for (std::size_t at = text.find("</"); at != std::string::npos; at = text.find("</", at + 3))
    text.replace(at, 2, "<\\/");
  return text;
}

} // namespace

std::string figure_html(const nlohmann::json& figure, const std::string& caption) {
  if (figure.is_null()) return {};
  return fmt::format("<figure class=\"evidence\" data-kind=\"{}\"><div class=\"plot\"></div>"
                     "<script type=\"application/json\" class=\"figure-data\">{}</script>"
                     "<figcaption>{}</figcaption></figure>\n",
                     xml_escape(figure.value("kind", "")), script_safe(figure.dump()), caption);
}

std::string figure_styles() {
  return fmt::format("<style>{}</style>\n<style>.plot .notes{{font-size:.8em;color:#57606a}}"
                     ".plot .lane-title{{font-size:.75em;color:#57606a;margin:0 0 0 1em}}</style>\n",
                     report_assets::uplot_css());
}

std::string figure_scripts() {
  // Neither holds "</" (report_assets_test): their bytes go in as npm and the repository have them.
  return fmt::format("<script>{}</script>\n<script>{}</script>\n", report_assets::uplot_js(),
                     report_assets::figures_js());
}

} // namespace hilrig::rig
