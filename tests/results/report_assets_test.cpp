// The report's front end embedded in hilrig (rig/results/report_assets.hpp): byte for byte the
// files npm installed for the version report-web/package-lock.json pins (npm ci checked their
// tarball against the lock's integrity hash), and figures.js as the repository holds it.
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <string>

#include "rig/results/report_assets.hpp"

namespace hilrig::rig {
namespace {

const std::string kWeb = std::string(HILRIG_SOURCE_DIR) + "/report-web";

std::string file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  EXPECT_TRUE(in) << path;
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(ReportAssets, EmbeddedBytesAreTheInstalledPackageOfTheLockedVersion) {
  const auto lock = nlohmann::json::parse(file(kWeb + "/package-lock.json"));
  const auto& locked = lock["packages"]["node_modules/uplot"];
  const auto installed = nlohmann::json::parse(file(kWeb + "/node_modules/uplot/package.json"));
  EXPECT_EQ(installed["version"], locked["version"]);
  EXPECT_TRUE(locked["integrity"].get<std::string>().starts_with("sha512-"));
  EXPECT_EQ(report_assets::uplot_js(), file(kWeb + "/node_modules/uplot/dist/uPlot.iife.min.js"));
  EXPECT_EQ(report_assets::uplot_css(), file(kWeb + "/node_modules/uplot/dist/uPlot.min.css"));
  EXPECT_EQ(report_assets::figures_js(), file(kWeb + "/figures.js"));
  // A library of some size, not an empty or truncated file.
  EXPECT_GT(report_assets::uplot_js().size(), 40'000U);
  EXPECT_NE(report_assets::uplot_js().find("uPlot"), std::string::npos);
}

// Each goes into a <script> or <style> as it is: none may end its element early.
TEST(ReportAssets, NoneClosesItsElementEarly) {
  for (const std::string_view text :
       {report_assets::uplot_js(), report_assets::uplot_css(), report_assets::figures_js()})
    EXPECT_EQ(text.find("</"), std::string_view::npos);
}

} // namespace
} // namespace hilrig::rig
