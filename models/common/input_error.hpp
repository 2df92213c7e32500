// The one error type for bad user input: printed as "FILE:LINE: what" (or
// "FILE:@OFFSET: what" for a place in a binary file) and turned into exit
// code 2 by the CLI.
#pragma once

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>

namespace girtd {

class InputError : public std::runtime_error {
 public:
  InputError(std::string file, int line, const std::string& what)
      : std::runtime_error(what), file_(std::move(file)), line_(line) {}

  // A place in a binary file, counted in bytes from its start.
  static InputError at_byte(std::string file, uint64_t offset, const std::string& what) {
    InputError e(std::move(file), 0, what);
    e.offset_ = offset;
    return e;
  }

  const std::string& file() const { return file_; }
  int line() const { return line_; }
  std::optional<uint64_t> offset() const { return offset_; }
  // "FILE:LINE: what" (LINE omitted when unknown, i.e. 0), "FILE:@OFFSET: what".
  std::string formatted() const {
    std::string s = file_.empty() ? std::string("<input>") : file_;
    if (offset_) s += ":@" + std::to_string(*offset_);
    else if (line_ > 0) s += ":" + std::to_string(line_);
    return s + ": " + what();
  }

 private:
  std::string file_;
  int line_;
  std::optional<uint64_t> offset_;
};

}  // namespace girtd
