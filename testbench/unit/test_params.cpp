// Unit tests for models/config/params.hpp: the built-in configuration holds
// the thesis values of config/girtd.json, and overrides are strict.
#include <catch2/catch.hpp>

#include <string>

#include <nlohmann/json.hpp>

#include "common/input_error.hpp"
#include "config/params.hpp"

namespace girtd {
namespace {

using nlohmann::json;

// Runs with_overrides and returns the InputError it throws (fails the test
// when it does not throw).
InputError override_error(const json& j, const std::string& origin = "user.json") {
  try {
    Params::with_overrides(j, origin);
  } catch (const InputError& e) {
    return e;
  }
  FAIL("with_overrides(" << j.dump() << ") did not throw");
  return InputError("", 0, "");
}

// Every field except `source`, compared one by one.
void check_same_except_fifo_depth(const Params& a, const Params& b) {
  CHECK(a.screen_width == b.screen_width);
  CHECK(a.screen_height == b.screen_height);
  CHECK(a.ep_color == b.ep_color);
  CHECK(a.ep_t == b.ep_t);
  CHECK(a.ep_z == b.ep_z);
  CHECK(a.ep_d == b.ep_d);
  CHECK(a.xy_bits == b.xy_bits);
  CHECK(a.norm_frac_bits == b.norm_frac_bits);
  CHECK(a.prom_frac_bits == b.prom_frac_bits);
  CHECK(a.dda_clock_ns == b.dda_clock_ns);
  CHECK(a.xy_compare_pipelined == b.xy_compare_pipelined);
  CHECK(a.walk_fix == b.walk_fix);
  CHECK(a.output_latency_clocks == b.output_latency_clocks);
  CHECK(a.one_minus_nf == b.one_minus_nf);
  CHECK(a.had_access_ns == b.had_access_ns);
  CHECK(a.vram_cycle_ns == b.vram_cycle_ns);
  CHECK(a.depth_clear == b.depth_clear);
  CHECK(a.depth_max_mapped == b.depth_max_mapped);
  CHECK(a.target_mpixels_per_s == b.target_mpixels_per_s);
  CHECK(a.stage_flops_per_s == b.stage_flops_per_s);
}

}  // namespace

TEST_CASE("Params::defaults holds the thesis values of config/girtd.json", "[params]") {
  const Params p = Params::defaults();
  CHECK(p.screen_width == 1024);
  CHECK(p.screen_height == 1024);
  // Colour and T: 11.9, 8-bit output; Z: 18.8, 16-bit output; D: 12.12, no output.
  CHECK(p.ep_color == FixFormat{11, 9, 8});
  CHECK(p.ep_t == FixFormat{11, 9, 8});
  CHECK(p.ep_z == FixFormat{18, 8, 16});
  CHECK(p.ep_d == FixFormat{12, 12, 0});
  CHECK(p.xy_bits == 16);
  CHECK(p.norm_frac_bits == 8);
  CHECK(p.prom_frac_bits == 4);
  CHECK(p.dda_clock_ns == 35.0);
  CHECK(p.xy_compare_pipelined);
  CHECK(p.walk_fix);
  CHECK(p.output_latency_clocks == 1);
  CHECK(p.one_minus_nf == OneMinusNf::kExact);
  CHECK(p.had_access_ns == 25.0);
  CHECK(p.vram_cycle_ns == 220.0);
  CHECK(p.fifo_dda_had_depth == 16);
  CHECK(p.depth_clear == 65535);
  CHECK(p.depth_max_mapped == 65534);
  CHECK(p.target_mpixels_per_s == 20.0);
  CHECK(p.stage_flops_per_s == 1e7);
  // The merged JSON is kept for reports.
  CHECK(p.source.at("fifo").at("dda_had_depth") == 16);
}

TEST_CASE("with_overrides rejects an unknown key and names its full path", "[params]") {
  const InputError e = override_error(json{{"dda", {{"walk_fixx", false}}}});
  CHECK(e.file() == "user.json");
  CHECK_THAT(std::string(e.what()), Catch::Contains("dda.walk_fixx"));
  // A top-level typo too.
  const InputError e2 = override_error(json{{"fifoo", 1}});
  CHECK_THAT(std::string(e2.what()), Catch::Contains("fifoo"));
  // A key two levels down.
  const InputError e3 = override_error(json{{"ep", {{"color", {{"int_bit", 12}}}}}});
  CHECK_THAT(std::string(e3.what()), Catch::Contains("ep.color.int_bit"));
}

TEST_CASE("with_overrides rejects values of the wrong JSON type", "[params]") {
  // A number where a boolean is expected.
  const InputError e1 = override_error(json{{"dda", {{"walk_fix", 1}}}});
  CHECK_THAT(std::string(e1.what()), Catch::Contains("dda.walk_fix"));
  // A string where a number is expected.
  const InputError e2 = override_error(json{{"fifo", {{"dda_had_depth", "16"}}}});
  CHECK_THAT(std::string(e2.what()), Catch::Contains("fifo.dda_had_depth"));
  // A scalar where an object is expected.
  const InputError e3 = override_error(json{{"dda", 5}});
  CHECK_THAT(std::string(e3.what()), Catch::Contains("dda"));
  // A boolean where a string is expected.
  const InputError e4 = override_error(json{{"had", {{"one_minus_nf", true}}}});
  CHECK_THAT(std::string(e4.what()), Catch::Contains("had.one_minus_nf"));
  // The whole override must be an object.
  CHECK_THROWS_AS(Params::with_overrides(json::array({1, 2}), "user.json"), InputError);
}

TEST_CASE("a valid override changes only its own field", "[params]") {
  const Params base = Params::defaults();
  const Params p = Params::with_overrides(json{{"fifo", {{"dda_had_depth", 32}}}}, "user.json");
  CHECK(p.fifo_dda_had_depth == 32);
  check_same_except_fifo_depth(p, base);
  // An integer is accepted where the default is a real: 40 -> 40.0 ns.
  const Params q = Params::with_overrides(json{{"dda", {{"clock_ns", 40}}}}, "user.json");
  CHECK(q.dda_clock_ns == 40.0);
  CHECK(q.had_access_ns == 25.0);
  // An empty override is the built-in configuration.
  const Params r = Params::with_overrides(json::object(), "user.json");
  CHECK(r.fifo_dda_had_depth == 16);
  check_same_except_fifo_depth(r, base);
}

TEST_CASE("with_overrides rejects a fractional value for an integer field", "[params]") {
  // fifo.dda_had_depth and ep.*.int_bits are integers in config/girtd.json.
  // 16.5 is not a FIFO depth and 11.5 not a bit count: silently truncating
  // them to 16 and 11 would hide a typo, which the strict merge exists to catch.
  CHECK_THROWS_AS(Params::with_overrides(json{{"fifo", {{"dda_had_depth", 16.5}}}}, "u"), InputError);
  CHECK_THROWS_AS(Params::with_overrides(json{{"ep", {{"color", {{"int_bits", 11.5}}}}}}, "u"), InputError);
}

TEST_CASE("one_minus_nf accepts exact and invert_bits only", "[params]") {
  CHECK(Params::with_overrides(json{{"had", {{"one_minus_nf", "exact"}}}}, "u").one_minus_nf ==
        OneMinusNf::kExact);
  CHECK(Params::with_overrides(json{{"had", {{"one_minus_nf", "invert_bits"}}}}, "u").one_minus_nf ==
        OneMinusNf::kInvertBits);
  const InputError e = override_error(json{{"had", {{"one_minus_nf", "invert"}}}});
  CHECK_THAT(std::string(e.what()), Catch::Contains("one_minus_nf"));
  CHECK_THROWS_AS(Params::with_overrides(json{{"had", {{"one_minus_nf", "EXACT"}}}}, "u"), InputError);
}

TEST_CASE("with_overrides rejects formats the HAD cannot take", "[params]") {
  // The HAD multiplies 8-bit colours: a 9-bit colour output is refused.
  CHECK_THROWS_AS(Params::with_overrides(json{{"ep", {{"color", {{"out_bits", 9}}}}}}, "u"), InputError);
  // out_bits may not exceed int_bits (8 > 7).
  CHECK_THROWS_AS(Params::with_overrides(json{{"ep", {{"color", {{"int_bits", 7}}}}}}, "u"), InputError);
  // GIRTD's frame is 1024 x 1024.
  CHECK_THROWS_AS(Params::with_overrides(json{{"screen", {{"width", 512}}}}, "u"), InputError);
  // Clock periods must be positive.
  CHECK_THROWS_AS(Params::with_overrides(json{{"dda", {{"clock_ns", 0}}}}, "u"), InputError);
}

}  // namespace girtd
