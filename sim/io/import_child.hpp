// A model import in a child process (fork): a crash, an exhausted memory or
// a hang inside an importer becomes one InputError line naming the file,
// and this process goes on. The child's address space and the time it may
// take are bounded (ImportLimits); its answer (the mesh, its warnings, or
// the error) comes back through a pipe. The child leaves by _exit only: no
// exception, destructor or atexit handler of this process runs in it.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "io/model_import.hpp"

namespace girtd {

// The one line for an import that ran out of memory under `limits` (in the
// child, or caught by assimp itself and passed on as its error text).
std::string out_of_memory_message(const ImportLimits& limits);

// Called inside `import` (in the child): how much of the file it has read,
// 0..1, shown on the parent's progress line (io/progress_line.hpp).
void report_import_progress(double share);

// Runs `import` in a child under `limits`; returns its model and appends its
// warnings, or throws its InputError (or "FILE: cannot read the model: the
// importer ..." when it crashed, ran out of memory or time).
ImportedModel import_in_child(const std::string& path, const ImportLimits& limits,
                              const std::function<ImportedModel(std::vector<std::string>& warnings)>& import,
                              std::vector<std::string>& warnings);

}  // namespace girtd
