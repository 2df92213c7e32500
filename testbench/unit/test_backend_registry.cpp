// The back-end registry (sim/engine/backend_registry.cpp) against the design
// as docs/architecture.md's capability table states it, written out here by
// hand; and the frame driver every run goes through
// (sim/backends/frame_driver.hpp).
#include <catch2/catch.hpp>

#include <filesystem>
#include <set>

#include "accuracy/accuracy_levels.hpp"
#include "backends/frame_driver.hpp"
#include "common/input_error.hpp"
#include "engine/backend_registry.hpp"
#include "frontend/input_test_support.hpp"

namespace girtd {

TEST_CASE("the registry: each back end's capabilities, refusals and factory", "[registry]") {
  REQUIRE(backend_names() == std::vector<std::string>{"reference", "golden", "approx", "rtl"});
  const BackendEntry &reference = backend_named("reference"), &golden = backend_named("golden"),
                     &approx = backend_named("approx"), &rtl = backend_named("rtl");
  CHECK(reference.capabilities == (kSeesSurfaces | kExactPicture));
  CHECK(golden.capabilities == (kDrawsWithDda | kSeesSurfaces));
  CHECK(approx.capabilities == (kDrawsWithDda | kModelsTime | kSeesSurfaces | kSamplesTiming));
  CHECK(rtl.capabilities == (kDrawsWithDda | kModelsTime | kRunsRtl | kExactTiming));
  for (const BackendEntry& b : backend_registry()) {
    INFO(b.name);
    CHECK(bool(b.make));
    CHECK(!b.summary.empty());
    std::set<std::string> refused;
    for (const BackendRefusal& r : b.refuses) {
      CHECK(refused.insert(r.option).second);
      CHECK(!r.reason.empty());
    }
    // What it refuses is what it lacks: waveforms without the pipeline,
    // sampled timing without the sampler.
    CHECK(bool(b.refusal("--wave")) == !b.has(kModelsTime));
    CHECK(bool(b.refusal("--sample-timing")) == !b.has(kSamplesTiming));
  }
  CHECK(&backend_with(kExactPicture) == &reference);
  CHECK(&backend_with(kExactTiming) == &rtl);
  CHECK(find_backend("nosuch") == nullptr);
  CHECK_THROWS_AS(backend_named("nosuch"), std::logic_error);
  // One interface: the untimed back ends answer "not modeled" to the timing
  // questions, a timed one answers them.
  const Params p = Params::defaults();
  CHECK(reference.make(p, {})->modeled_time() == nullptr);
  CHECK(golden.make(p, {})->modeled_time() == nullptr);
  const std::unique_ptr<Backend> timed = approx.make(p, {});
  REQUIRE(timed->modeled_time() != nullptr);
  CHECK(timed->modeled_time()->now_tick() == 0);
}

TEST_CASE("the frame driver keeps each frame's picture only for --frames all and commits the dump at the end",
          "[registry]") {
  Trace t;
  t.path = "two_frames.trace";
  t.level = TraceLevel::kTriangle;
  t.frames.resize(2);
  const Params p = Params::defaults();
  RgbImage img;
  img.width = img.height = 1;
  img.rgb = {1, 2, 3};
  int reads = 0;
  auto shown = [&] { return ++reads, img; };

  const FrameSource input(t);
  RenderOptions plain;
  FrameDriver a("golden", input, p, plain);
  CHECK(a.tap() == nullptr);
  a.frame_ended(shown);
  a.frame_ended(shown);
  RenderOutput out_a;
  a.finish(out_a);
  CHECK(reads == 0);  // not kept: the picture is never read
  CHECK(out_a.per_frame.empty());

  RenderOptions keep;
  keep.keep_all_frames = true;
  const std::string dump = test::temp_file("frame_driver.trace", "");
  std::filesystem::remove(dump);
  keep.dump = DumpRequest{TraceLevel::kTriangle, dump};
  FrameDriver b("golden", input, p, keep);
  REQUIRE(b.tap() != nullptr);
  for (const TraceFrame& f : t.frames) {
    b.tap()->frame(f);
    b.frame_ended(shown);
  }
  CHECK(!std::filesystem::exists(dump));  // nothing half-written
  RenderOutput out_b;
  b.finish(out_b);
  CHECK(reads == 2);
  CHECK(out_b.per_frame.size() == 2);
  CHECK(std::filesystem::exists(dump));

  RenderOptions hand_on;  // --frames all: each frame handed on as it ends, none held
  std::vector<size_t> handed;
  hand_on.on_frame = [&](size_t i, const RgbImage& picture) {
    CHECK(picture.rgb == img.rgb);
    handed.push_back(i);
  };
  FrameDriver c("golden", input, p, hand_on);
  c.frame_ended(shown);
  c.frame_ended(shown);
  RenderOutput out_c;
  c.finish(out_c);
  CHECK(handed == std::vector<size_t>{0, 1});
  CHECK(reads == 4);
  CHECK(out_c.per_frame.empty());
}

// girtd accuracy's levels come from the registry's capabilities: the list
// as the accuracy command has always run it, written out by hand.
TEST_CASE("accuracy levels: the default list and the estimators, from capabilities", "[registry]") {
  const std::vector<BackendEntry>& r = backend_registry();
  CHECK(default_accuracy_levels(r) ==
        std::vector<std::string>{"rtl", "approx", "dda_bound", "approx_sampled_0.1", "approx_sampled_0.02"});
  const AccuracyLevel bound = accuracy_level("dda_bound", r);
  CHECK(bound.backend == "golden");
  CHECK(bound.modeled_time_key == "dda_bound_time_s");
  const AccuracyLevel sampled = accuracy_level("approx_sampled_0.1", r);
  CHECK(sampled.backend == "approx");
  CHECK(sampled.render_args == std::vector<std::string>{"--sample-timing", "0.1"});
  CHECK_FALSE(sampled.draws_frame);
  CHECK(accuracy_level("rtl", r).timing_yardstick);
  CHECK(accuracy_level("reference", r).picture_yardstick);
  CHECK_THROWS_AS(accuracy_level("approx_sampled_2", r), InputError);
  CHECK_THROWS_AS(accuracy_level("fast", r), InputError);
}

}  // namespace girtd
