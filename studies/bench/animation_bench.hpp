// girtd bench --scale's long animations: is a run's memory flat in its
// frame count? A generated UV sphere (tools/make_mesh.py, written by the
// driver) turning in a scene of N frames, rendered end to end as a user runs
// it, at a short and a long frame count: golden and approx at 10 and 1,000
// frames, rtl at 10 and 100. The bar: the long run's peak resident memory
// at most 1.1 times the short one's.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace girtd {

inline constexpr long kAnimationTriangles = 2000;
inline constexpr long kShortAnimation = 10, kLongAnimation = 1000, kLongAnimationRtl = 100;

struct AnimationBench {
  nlohmann::json rows;  // one per back end
  std::string markdown;
  int failures = 0;
};

// The driver's plan: the turning sphere's mesh ("mesh\tTRIANGLES\tPATH").
std::vector<std::string> animation_bench_plan_lines(const std::string& out_dir);

// `long_frames`: golden's and approx's long count (rtl's is at most kLongAnimationRtl).
AnimationBench run_animation_bench(const std::string& out_dir, long short_frames, long long_frames);

}  // namespace girtd
