// --backend approx: the golden DDA and HAD for what is drawn, the timing
// model (sim/dda, sim/had) for when.
#pragma once

#include <memory>
#include <optional>

#include "backends/backend.hpp"
#include "config/params.hpp"

namespace girtd {

std::unique_ptr<Backend> make_approx_backend(const Params& p, std::optional<double> sample_rate);

}  // namespace girtd
