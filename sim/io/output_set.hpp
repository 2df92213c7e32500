// Output files of one run, written under temporary names and moved into
// place together at the end: an error leaves nothing half-written.
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace girtd {

// Outputs are written only after a run: find out before it whether they
// can be (an existing file where a directory must go is bad usage,
// InputError(option, 0, ...)).
void check_output_dir(const std::string& dir, const char* option);

class OutputSet {
 public:
  explicit OutputSet(std::string dir) : dir_(std::move(dir)) {}
  // Uncommitted: the temporary files go, and the directories this made.
  ~OutputSet();
  // `write(tmp_path)` writes the file's content to the temporary path, at commit().
  void add(const std::string& name, const std::function<void(const std::string&)>& write);
  void add_text(const std::string& name, const std::string& text);  // or any bytes
  // The same, written now (a long run's frames as they end), moved into
  // place with the others.
  void write_now(const std::string& name, const std::function<void(const std::string&)>& write);
  // Creates the directory and renames every file into place.
  void commit();
  std::string path(const std::string& name) const { return dir_ + "/" + name; }

 private:
  void make_dir();
  std::string write_tmp(const std::string& name, const std::function<void(const std::string&)>& write);

  std::string dir_;
  std::vector<std::string> made_dirs_;  // the deepest first
  std::vector<std::string> names_;
  std::vector<std::function<void(const std::string&)>> writers_;
  std::vector<std::string> done_names_, done_tmp_;  // written: each name's temporary file
  bool committed_ = false;
};

}  // namespace girtd
