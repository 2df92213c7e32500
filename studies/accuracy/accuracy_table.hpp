// `girtd accuracy`'s tables: the rows' picture-error cells, the per-level
// summary (mean and maximum |time error| against rtl, cases under 1 % and
// 10 %, the Pareto front of wall time against maximum error), the counters'
// differences, and the rows as Markdown and CSV.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "io/image_compare.hpp"

namespace girtd {

// The contract's image / llvmpipe cell.
nlohmann::json picture_error_cell(const ImageError& image, const DepthError& depth);

// Per timing level over the rows that have a time_error.
nlohmann::json level_summary(const nlohmann::json& rows);
// Per level and counter: mean and maximum relative difference from rtl.
nlohmann::json counter_summary(const nlohmann::json& rows);

// Per input x variant with a row of the timing yardstick (`yardstick`, the
// RTL): does every other complete level's frame equal its, byte for byte
// (golden, approx and rtl draw one picture)? The picture yardstick
// (`exact`, double precision) is not compared.
nlohmann::json rtl_agreement(const nlohmann::json& rows, const std::string& yardstick, const std::string& exact);

std::string accuracy_markdown(const nlohmann::json& rows, const nlohmann::json& levels, const nlohmann::json& counters,
                              const nlohmann::json& agreement);
// The variants' formats: EP errors after 1,024 and 2,048 steps against the
// budget, and the register and adder bits they cost.
std::string variants_markdown(const nlohmann::json& variants);

std::string accuracy_csv(const nlohmann::json& rows);

}  // namespace girtd
