// Parses traces/FORMAT.md. Every problem is an InputError "FILE:LINE: what".
#pragma once

#include <iosfwd>
#include <optional>
#include <string>

#include "config/params.hpp"
#include "io/trace.hpp"

namespace girtd {

// `forced_level` is --level: required for a headerless file, and must agree
// with the header when there is one. DDA-level values are checked against
// the EP formats of `params`.
Trace read_trace(const std::string& path, std::optional<TraceLevel> forced_level, const Params& params);
Trace read_trace(std::istream& in, const std::string& path, std::optional<TraceLevel> forced_level,
                 const Params& params);

// True when the file's first record is a girtd-trace header.
bool has_trace_header(const std::string& path);
// The level its header names (nullopt: no header; InputError: an unknown level).
std::optional<TraceLevel> header_level(const std::string& path);

}  // namespace girtd
