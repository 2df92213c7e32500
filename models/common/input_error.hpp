// The one error type for bad user input: printed as "FILE:LINE: what" (or
// "FILE:@OFFSET: what" for a place in a binary file) and turned into exit
// code 2 by the CLI.
#pragma once

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>

namespace girtd {

// `text` on one line: a control character (a newline in a name a file gave,
// in an importer's message) written as \xNN, so that an error stays one line.
inline std::string one_line(const std::string& text) {
  static const char* const kHex = "0123456789abcdef";
  std::string out;
  out.reserve(text.size());
  for (const char ch : text) {
    const unsigned char c = static_cast<unsigned char>(ch);
    if (c >= 0x20 && c != 0x7f) {
      out += ch;
    } else {
      out += "\\x";
      out += kHex[c >> 4];
      out += kHex[c & 15];
    }
  }
  return out;
}

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
  // "FILE:LINE: what" (LINE omitted when unknown, i.e. 0), "FILE:@OFFSET: what",
  // always one line.
  std::string formatted() const {
    std::string s = file_.empty() ? std::string("<input>") : file_;
    if (offset_) s += ":@" + std::to_string(*offset_);
    else if (line_ > 0) s += ":" + std::to_string(line_);
    return one_line(s + ": " + what());
  }

 private:
  std::string file_;
  int line_;
  std::optional<uint64_t> offset_;
};

}  // namespace girtd
