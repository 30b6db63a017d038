#pragma once
// report.html: one self-contained page (inline CSS and SVG, no external resources) a person
// reads after a campaign: verdict summary, fault detection matrix, every measurement against
// its limits, timing diagrams for edge/advance checks and latency histograms for throughput.

#include <string>

#include "rig/results/campaign_result.hpp"

namespace hilrig::rig {

[[nodiscard]] std::string to_report_html(const CampaignResult& result);

} // namespace hilrig::rig
