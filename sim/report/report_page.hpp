// report.html: one self-contained page of a render's report that opens
// offline (everything inlined): the frame and, on approx, two heat maps
// beside it (page misses per cache page; the share of DDA clocks wasted by
// the last triangle drawn at each pixel), the throughput verdict and where
// the time went, a timeline per SystemC stage (busy, starved, blocked over
// modeled time) and the occupancy of the FIFO in front of each, the pixel
// accounting, warnings, numerics, what was left out, the configuration.
// Charts: uPlot (npm, sim/report/web), installed into the build by
// tools/girtd and inlined here; nothing is fetched when the page opens.
#pragma once

#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "backends/run_stats.hpp"
#include "io/png_io.hpp"
#include "report/page_parts.hpp"

namespace girtd {

// The page's data: the report, the timelines (per stage: its bins'
// starved, busy and blocked seconds and its input FIFO's peak occupancy),
// the page misses per cache page (approx).
nlohmann::json report_page_data(const nlohmann::json& report, const RunStats& s);

// The frame against another back end's (render --compare reference): the
// largest channel difference per pixel, as a histogram and a heat map.
struct FrameComparison {
  std::string against;  // the other back end
  RgbImage frame;       // its frame
};

// `frame_png`: the frame as frame.png holds it (encoded once). `s.maps`'
// DDA waste map and the comparison's heat map are inlined as pictures
// (their pixels coloured here).
std::string report_html(nlohmann::json page_data, const RgbImage& frame, const std::string& frame_png,
                        const RunStats& s, const std::optional<FrameComparison>& compare,
                        const std::optional<ChartLibrary>& charts);

}  // namespace girtd
