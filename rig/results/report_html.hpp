#pragma once
// report.html: one self-contained page (no external resources: uPlot and the figures' script
// are embedded, figure_html.hpp) a person reads after a campaign: failures first, traceability,
// fault detection matrix, every measurement against its limits, timing diagrams around the
// judged windows, latency histograms, debounce probes and the brake's stop.

#include <string>

#include "rig/results/campaign_result.hpp"
#include "rig/results/run_source.hpp"

namespace hilrig::rig {

[[nodiscard]] std::string to_report_html(const CampaignResult& result);
// The same page for `header` (finalized) with the runs `runs` gives, one at a time. The first
// 100 runs that did not pass and the first 20 that passed have a full section; the others are
// one row each of a table (with a link to their trace), and each summary list names its first
// 100 entries and counts the rest, so the page of a long campaign stays readable and its
// writer holds one run at a time.
void write_report_html(const CampaignResult& header, const RunSource& runs, const TextSink& out);

} // namespace hilrig::rig
