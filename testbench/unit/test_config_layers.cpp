// --config files layered over config/girtd.json (models/config): merged in
// order, the later winning, and a refused value reported at the line of the
// file that set it. Lines are counted by hand in the texts below.
#include <catch2/catch.hpp>

#include <string>

#include "common/json_text.hpp"
#include "common/types.hpp"
#include "config/params.hpp"
#include "frontend/input_test_support.hpp"

namespace girtd {
namespace {

using test::error_of;
using test::temp_file;

}  // namespace

TEST_CASE("json_key_lines gives each key's line by dotted path", "[params]") {
  const std::string text =
      "{\n"                                  // 1
      "  \"a\": 1,\n"                        // 2
      "  \"b\": {\n"                         // 3
      "    \"c\": [ {\"in_array\": 2} ],\n"  // 4
      "    \"d\": { \"e\": \"x:y\" }\n"      // 5
      "  },\n"                               // 6
      "  \"f\": true }\n";                   // 7
  const std::map<std::string, int> lines = json_key_lines(text);
  CHECK(lines.at("a") == 2);
  CHECK(lines.at("b") == 3);
  CHECK(lines.at("b.c") == 4);
  CHECK(lines.at("b.d") == 5);
  CHECK(lines.at("b.d.e") == 5);
  CHECK(lines.at("f") == 7);
  CHECK(lines.count("b.c.in_array") == 0);  // inside an array: not a config key
  CHECK(lines.size() == 6);
}

TEST_CASE("configuration files merge in order and the later wins", "[params]") {
  const std::string a = temp_file("cfg_a.json", "{ \"fifo\": { \"dda_had_depth\": 8 }, \"had\": { \"access_ns\": 30 } }");
  const std::string b = temp_file("cfg_b.json", "{ \"fifo\": { \"dda_had_depth\": 4 } }");
  const Params ab = Params::from_files({a, b});
  CHECK(ab.fifo_dda_had_depth == 4);
  CHECK(ab.had_access_ns == 30.0);  // a's, which b does not set
  const Params ba = Params::from_files({b, a});
  CHECK(ba.fifo_dda_had_depth == 8);
  CHECK(Params::from_files({}).fifo_dda_had_depth == 16);  // config/girtd.json
}

TEST_CASE("the design's constants are in the configuration and cannot be changed", "[params]") {
  // config/constants.json's values, as the thesis fixes them (docs/design.md):
  // a 1024 x 1024 screen, 8-bit colour and T, 16-bit Z, nf with 8 fraction bits.
  const Params d = Params::defaults();
  CHECK(d.screen_width == 1024);
  CHECK(d.screen_height == 1024);
  CHECK(d.ep_color.out_bits == 8);
  CHECK(d.ep_t.out_bits == 8);
  CHECK(d.ep_z.out_bits == 16);
  CHECK(d.norm_frac_bits == 8);
  CHECK(kNfOne == 256);
  CHECK(d.source.at("screen").at("width") == 1024);  // echoed in report.json's config like any key
  // The same value is no change; another is refused at its line, with the reason.
  const std::string same = temp_file("cfg_same.json", "{\"ep\": {\"z\": {\"out_bits\": 16}}}");
  CHECK(error_of([&] { Params::from_files({same}); }).empty());
  const std::string z12 = temp_file("cfg_z12.json",
                                    "{\n"
                                    "  \"ep\": {\n"
                                    "    \"z\": { \"out_bits\": 12 }\n"
                                    "  }\n"
                                    "}\n");
  CHECK(error_of([&] { Params::from_files({z12}); }) ==
        z12 + ":3: ep.z.out_bits: fixed by the design at 16 (the VRAM holds 16-bit Z): not a setting");
}

TEST_CASE("a refused configuration value is reported at the line that set it", "[params]") {
  const std::string depth40 = temp_file("cfg_depth40.json",
                                        "{\n"
                                        "  \"had\": { \"access_ns\": 30.0 },\n"
                                        "  \"fifo\": {\n"
                                        "    \"dda_had_depth\": 40\n"
                                        "  }\n"
                                        "}\n");
  // A relation with a value of config/girtd.json (max_depth 32).
  CHECK(error_of([&] { Params::from_files({depth40}); }) ==
        depth40 + ":4: fifo.dda_had_depth: fifo.dda_had_depth must be at most fifo.max_depth");
  // The other side of the relation: a user file that lowers max_depth is blamed.
  const std::string max8 = temp_file("cfg_max8.json", "{\n\n  \"fifo\": {\"max_depth\": 8}}");
  CHECK(error_of([&] { Params::from_files({max8}); }) ==
        max8 + ":3: fifo.max_depth: fifo.dda_had_depth must be at most fifo.max_depth");
  // A later file that sets the key again takes the blame away.
  const std::string depth8 = temp_file("cfg_depth8.json", "{\n\"fifo\": {\"dda_had_depth\": 8}}");
  CHECK(error_of([&] { Params::from_files({depth40, depth8}); }).empty());
  // An unknown key, a wrong type, a period that is no multiple of the tick.
  const std::string typo = temp_file("cfg_typo.json", "{\n\n  \"had\": {\"acess_ns\": 30}}");
  CHECK(error_of([&] { Params::from_files({typo}); }) == typo + ":3: had.acess_ns: unknown configuration key");
  const std::string type = temp_file("cfg_type.json", "{\"dda\": {\n \"walk_fix\": 1}}");
  CHECK(error_of([&] { Params::from_files({type}); }) == type + ":2: dda.walk_fix: has the wrong type (expected boolean)");
  const std::string tick = temp_file("cfg_tick.json", "{\"had\": {\"access_ns\": 27.0}}");
  CHECK(error_of([&] { Params::from_files({tick}); }) ==
        tick + ":1: had.access_ns: must be a multiple of timing.base_tick_ns");
  // A base tick that no longer divides a built-in period blames that period
  // where config/girtd.json sets it.
  const std::string base = temp_file("cfg_base.json", "{\"timing\": {\"base_tick_ns\": 4.0}}");
  CHECK_THAT(error_of([&] { Params::from_files({base}); }),
             Catch::Matches("config/girtd\\.json:[0-9]+: dda\\.clock_ns: must be a multiple of timing\\.base_tick_ns"));
}

}  // namespace girtd
