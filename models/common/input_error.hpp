// The one error type for bad user input: printed as "FILE:LINE: what" (or
// "FILE:@OFFSET: what" for a place in a binary file) and turned into exit
// code 2 by the CLI.
#pragma once

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>

namespace girtd {

// The length of the valid UTF-8 sequence at text[i] (no overlong forms, no
// surrogates), or 0.
inline size_t utf8_length(const std::string& text, size_t i) {
  const auto at = [&](size_t k) { return static_cast<unsigned char>(text[k]); };
  const unsigned char c = at(i);
  size_t n = 0;
  unsigned char lo = 0x80, hi = 0xbf;  // the second byte's range
  if (c >= 0xc2 && c <= 0xdf) n = 2;
  else if (c >= 0xe0 && c <= 0xef) n = 3, lo = c == 0xe0 ? 0xa0 : 0x80, hi = c == 0xed ? 0x9f : 0xbf;
  else if (c >= 0xf0 && c <= 0xf4) n = 4, lo = c == 0xf0 ? 0x90 : 0x80, hi = c == 0xf4 ? 0x8f : 0xbf;
  if (n == 0 || i + n > text.size() || at(i + 1) < lo || at(i + 1) > hi) return 0;
  for (size_t k = 2; k < n; ++k)
    if (at(i + k) < 0x80 || at(i + k) > 0xbf) return 0;
  return n;
}

// `text` on one line and valid UTF-8: a control character (a newline in a
// name a file gave, in an importer's message) or a byte of no UTF-8
// character is written as \xNN, so that an error stays one line and a
// report's JSON can hold it.
inline std::string one_line(const std::string& text) {
  static const char* const kHex = "0123456789abcdef";
  std::string out;
  out.reserve(text.size());
  for (size_t i = 0; i < text.size();) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    const size_t n = c < 0x80 ? (c >= 0x20 && c != 0x7f ? 1 : 0) : utf8_length(text, i);
    if (n > 0) {
      out.append(text, i, n);
      i += n;
    } else {
      out += "\\x";
      out += kHex[c >> 4];
      out += kHex[c & 15];
      ++i;
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
