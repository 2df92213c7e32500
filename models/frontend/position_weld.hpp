// A model's coordinate table as its corners are read: a position met before
// (bit-identical, -0 and 0 alike) gets the index it got then, so corners at
// one position are one vertex. Model files (sim/io/model_import) and a
// scene's inline meshes weld alike.
#pragma once

#include <absl/container/flat_hash_map.h>

#include <tuple>
#include <vector>

#include "common/equal_keys.hpp"
#include "frontend/vec3.hpp"

namespace girtd {

class PositionWeld {
 public:
  // `p`'s index in `positions`, appended there when it is new.
  int index_of(const Vec3& p, std::vector<Vec3>& positions) {
    auto [it, fresh] = index_.try_emplace(std::make_tuple(same_zero(p.x), same_zero(p.y), same_zero(p.z)),
                                          static_cast<int>(positions.size()));
    if (fresh) positions.push_back(p);
    return it->second;
  }

 private:
  absl::flat_hash_map<std::tuple<double, double, double>, int> index_;
};

}  // namespace girtd
