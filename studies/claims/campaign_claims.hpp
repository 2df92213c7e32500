// Chapter 5's memory-side claims read from the study campaign's stored
// results (results/sweeps/study_coarse/results.json, checked
// in), so `claims` stays fast: the thesis' timings with the memory side as
// written, with write-behind, and with write-behind and prefetch, each input
// run as 8 frames. Without the file every row says "not yet measured".
#pragma once

#include <string>
#include <vector>

namespace girtd {

struct ClaimRow {
  std::string claim, thesis, measured, verdict;
};

inline constexpr const char* kCampaignResults = "results/sweeps/study_coarse/results.json";

std::vector<ClaimRow> campaign_claims(const std::string& results_path = kCampaignResults);

}  // namespace girtd
