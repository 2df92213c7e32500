// What flows through the pipeline's FIFOs: a frame's opening marker, its
// items, its closing marker, and the end of the run. Stages that hold a
// whole frame (projection, depth sort) act on the closing marker.
#pragma once

#include <cstddef>
#include <ostream>

namespace girtd {

enum class TokenKind { kFrameBegin, kItem, kFrameEnd, kEnd };

template <typename T>
struct Token {
  TokenKind kind = TokenKind::kEnd;
  size_t frame = 0;  // index into the trace's frames
  T item{};
};

// sc_fifo<T> needs T printable.
template <typename T>
std::ostream& operator<<(std::ostream& os, const Token<T>& t) {
  return os << "token(kind " << static_cast<int>(t.kind) << ", frame " << t.frame << ")";
}

}  // namespace girtd
