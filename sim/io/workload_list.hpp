// The sample workloads (traces/workloads.txt): the one list `bench`,
// `regress` and the stored expectations run.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "io/trace.hpp"

namespace girtd {

constexpr const char* kWorkloadList = "traces/workloads.txt";

// Every listed input, in the list's order. InputError when the list is
// missing (run from the repository root) or names a file that is not there.
std::vector<std::string> sample_workloads();
// Any such list (one input per line, `#` comments), e.g. traces/accuracy_inputs.txt.
std::vector<std::string> read_input_list(const std::string& list);

// The listed traces whose header says one of `levels` (models and scenes
// have no header and are left out).
std::vector<std::string> sample_traces_at(const std::vector<TraceLevel>& levels);

}  // namespace girtd
