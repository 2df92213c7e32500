#include "io/output_set.hpp"

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "common/input_error.hpp"

namespace girtd {

namespace fs = std::filesystem;

void check_output_dir(const std::string& dir, const char* option) {
  for (fs::path p = fs::absolute(dir.empty() ? "." : dir); !p.empty(); p = p.parent_path()) {
    std::error_code ec;
    if (fs::exists(p, ec)) {
      if (!fs::is_directory(p, ec)) throw InputError(option, 0, "'" + p.string() + "' is a file, not a directory");
      return;
    }
    if (p == p.parent_path()) return;
  }
}

OutputSet::~OutputSet() {
  if (committed_) return;
  std::error_code ec;
  for (const std::string& t : written_tmp_) fs::remove(t, ec);
}

void OutputSet::add(const std::string& name, const std::function<void(const std::string&)>& write) {
  names_.push_back(name);
  writers_.push_back(write);
}

void OutputSet::add_text(const std::string& name, const std::string& text) {
  add(name, [text](const std::string& tmp) {
    std::ofstream out(tmp);
    out << text;
    if (!out) throw InputError(tmp, 0, "cannot write file");
  });
}

void OutputSet::commit() {
  std::error_code ec;
  fs::create_directories(dir_, ec);
  if (ec) throw InputError(dir_, 0, "cannot create output directory: " + ec.message());
  for (size_t i = 0; i < names_.size(); ++i) {
    const std::string tmp = path("." + names_[i] + ".partial");
    written_tmp_.push_back(tmp);
    writers_[i](tmp);
  }
  for (size_t i = 0; i < names_.size(); ++i) {
    fs::rename(written_tmp_[i], path(names_[i]), ec);
    if (ec) throw InputError(path(names_[i]), 0, "cannot move output into place: " + ec.message());
  }
  committed_ = true;
}

}  // namespace girtd
