// One JSON document read from a file this program wrote: a child render's
// report.json, a sweep row. (Inputs a user wrote go through input_reader and
// the config loader, which say FILE:LINE for what is wrong.)
#pragma once

#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

namespace girtd {

inline nlohmann::json read_json_file(const std::string& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in);
}

}  // namespace girtd
