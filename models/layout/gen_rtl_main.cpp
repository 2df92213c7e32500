// girtd_gen_rtl [--config FILE]... OUT_DIR: writes girtd_pkg.sv,
// dda_prom_table.svh and rtl_build.hpp for the configuration (the built-in
// config/girtd.json with the files merged over it). A file whose text is
// unchanged is not touched, so nothing rebuilds for nothing. Exit 2 with
// "FILE:LINE: key: what" on a refused configuration.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "common/file_text.hpp"
#include "common/input_error.hpp"
#include "config/params.hpp"
#include "layout/rtl_package.hpp"

namespace {

using girtd::read_file_text;

void write_if_changed(const std::filesystem::path& path, const std::string& text) {
  if (read_file_text(path.string()) == text) return;
  const std::filesystem::path partial = path.string() + ".partial";
  std::ofstream(partial, std::ios::binary) << text;
  std::filesystem::rename(partial, path);
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> configs;
  std::string out_dir;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--config" && i + 1 < argc) configs.push_back(argv[++i]);
    else if (out_dir.empty() && a.rfind("--", 0) != 0) out_dir = a;
    else {
      std::fprintf(stderr, "usage: girtd_gen_rtl [--config FILE]... OUT_DIR\n");
      return 2;
    }
  }
  if (out_dir.empty()) {
    std::fprintf(stderr, "usage: girtd_gen_rtl [--config FILE]... OUT_DIR\n");
    return 2;
  }
  try {
    const girtd::Params p = girtd::Params::from_files(configs);
    std::filesystem::create_directories(out_dir);
    write_if_changed(std::filesystem::path(out_dir) / "girtd_pkg.sv", girtd::sv_package_text(p));
    write_if_changed(std::filesystem::path(out_dir) / "dda_prom_table.svh", girtd::sv_prom_table_text(p));
    write_if_changed(std::filesystem::path(out_dir) / "rtl_build.hpp", girtd::rtl_build_header_text(p));
  } catch (const girtd::InputError& e) {
    std::fprintf(stderr, "%s\n", e.formatted().c_str());
    return 2;
  }
  return 0;
}
