// The scene's "random_strengths" key (docs/scene-format.md): the joint and block material
// strengths, and the water table's fill, that `dda fos --samples` draws at random. Every mistake is one InputError at its
// place in the file; nothing is defaulted.
#pragma once

#include <optional>
#include <vector>

#include "io/json_input.hpp"
#include "solver/scene.hpp"

namespace dda {

RandomStrengths read_random_strengths(const input::Field& f,
                                      const std::vector<JointMaterial>& joint_materials,
                                      const std::vector<Material>& materials,
                                      const std::optional<WaterTable>& water);

}  // namespace dda
