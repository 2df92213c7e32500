// approx: the golden DDA and HAD for what is drawn, models/timing's timing
// model for when (backends/backend_engine.hpp).
#pragma once

#include <memory>
#include <optional>

#include "backends/backend_engine.hpp"
#include "config/params.hpp"

namespace girtd {

std::unique_ptr<BackendEngine> make_approx_engine(const Params& p, std::optional<double> sample_rate);

}  // namespace girtd
