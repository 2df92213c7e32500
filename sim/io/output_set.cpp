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
  for (const std::string& t : done_tmp_) fs::remove(t, ec);
  for (const std::string& d : made_dirs_) fs::remove(d, ec);  // each only when empty
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

void OutputSet::make_dir() {
  std::error_code ec;
  if (fs::is_directory(dir_, ec)) return;
  std::vector<std::string> missing;
  for (fs::path p = fs::absolute(dir_, ec); !p.empty() && !fs::exists(p, ec) && p != p.parent_path(); p = p.parent_path())
    missing.push_back(p.string());
  fs::create_directories(dir_, ec);
  if (ec) throw InputError(dir_, 0, "cannot create output directory: " + ec.message());
  made_dirs_ = std::move(missing);
}

std::string OutputSet::write_tmp(const std::string& name, const std::function<void(const std::string&)>& write) {
  const std::string tmp = path("." + name + ".partial");
  done_names_.push_back(name);
  done_tmp_.push_back(tmp);
  write(tmp);
  return tmp;
}

void OutputSet::write_now(const std::string& name, const std::function<void(const std::string&)>& write) {
  make_dir();
  write_tmp(name, write);
}

void OutputSet::commit() {
  make_dir();
  for (size_t i = 0; i < names_.size(); ++i) write_tmp(names_[i], writers_[i]);
  std::error_code ec;
  for (size_t i = 0; i < done_names_.size(); ++i) {
    fs::rename(done_tmp_[i], path(done_names_[i]), ec);
    if (ec) throw InputError(path(done_names_[i]), 0, "cannot move output into place: " + ec.message());
  }
  committed_ = true;
}

}  // namespace girtd
