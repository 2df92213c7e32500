// The one error type for bad user input: printed as "FILE:LINE: what" and
// turned into exit code 2 by the CLI.
#pragma once

#include <stdexcept>
#include <string>

namespace girtd {

class InputError : public std::runtime_error {
 public:
  InputError(std::string file, int line, const std::string& what)
      : std::runtime_error(what), file_(std::move(file)), line_(line) {}

  const std::string& file() const { return file_; }
  int line() const { return line_; }
  // "FILE:LINE: what" (LINE omitted when unknown, i.e. 0).
  std::string formatted() const {
    std::string s = file_.empty() ? std::string("<input>") : file_;
    if (line_ > 0) s += ":" + std::to_string(line_);
    return s + ": " + what();
  }

 private:
  std::string file_;
  int line_;
};

}  // namespace girtd
