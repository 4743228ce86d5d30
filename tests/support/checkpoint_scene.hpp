// The scene the checkpoint tests stop and continue (tests/io/test_checkpoint.cpp,
// tests/app/test_checkpoint_cli.cpp).
#pragma once

#include <string>

namespace dda::test {

// A staged scene with a bit of everything a checkpoint must carry: a Mohr-Coulomb block
// that yields and hardens under a heavy block, a block sliding on a 30 degree slope against
// 20 degrees of friction (contacts carry their sliding state), a bonded joint (cohesion,
// bonds formed by the first stage), a bolt, a monitor, a point load, and two stages: a
// static gravity ramp (10 steps of 5 ms) and a dynamic stage (16 steps at the default
// duration; longer for a run to interrupt).
inline std::string checkpoint_scene(const std::string& dynamic_duration = "0.08",
                                    const std::string& linear_solver = "factorise") {
  std::string text = R"json({
  "gravity": [0.0, -9.81],
  "control": {"time_step": 0.005, "max_displacement_ratio": 0.01, "output_every": 3,
              "linear_solver": "SOLVER"},
  "materials": {
    "soil": {"model": "mohr_coulomb", "density": 20.0, "young": 5.0e7, "poisson": 0.3,
             "cohesion": 2.0e3, "friction_angle": 10.0, "dilation_angle": 10.0,
             "hardening": [[0.0, 2.0e3], [0.01, 6.0e3]]},
    "weight": {"model": "elastic", "density": 20000.0, "young": 1.0e9, "poisson": 0.25},
    "rock": {"model": "elastic", "density": 2700.0, "young": 1.0e9, "poisson": 0.25}
  },
  "joint_materials": {
    "default": {"friction_angle": 20.0, "cohesion": 0.0, "tensile_strength": 0.0},
    "glued": {"friction_angle": 35.0, "cohesion": 1.0e3, "tensile_strength": 1.0e3}
  },
  "joints": [{"blocks": [1, 2], "material": "glued"}],
  "blocks": [
    {"vertices": [[-1.0, -1.0], [2.0, -1.0], [2.0, 0.0], [-1.0, 0.0]], "material": "weight", "fixed": true},
    {"vertices": [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]], "material": "soil"},
    {"vertices": [[0.0, 1.0], [1.0, 1.0], [1.0, 1.5], [0.0, 1.5]], "material": "weight"},
    {"vertices": [[2.6794919243112254, -10.0], [37.320508075688775, -10.0], [37.320508075688775, 10.0]],
     "material": "rock", "fixed": true},
    {"vertices": [[19.566987298107782, -0.25], [20.433012701892219, 0.25],
                  [20.183012701892219, 0.6830127018922193], [19.316987298107781, 0.18301270189221935]],
     "material": "rock"}
  ],
  "monitors": [{"name": "slider", "point": [19.9, 0.2]}],
  "point_loads": [{"point": [0.5, 1.25], "force": [100.0, 0.0]}],
  "bolts": [{"name": "b1", "from": [0.9, 0.5], "to": [1.5, -0.5], "stiffness": 1.0e6,
             "pretension": 0.0, "yield_force": 50.0}],
  "stages": [
    {"duration": 0.05, "dynamic_coefficient": 0, "gravity_ramp": [0, 1], "bond_closed_contacts": true},
    {"duration": DURATION, "dynamic_coefficient": 1}
  ]
})json";
  text.replace(text.find("DURATION"), 8, dynamic_duration);
  return text.replace(text.find("SOLVER"), 6, linear_solver);
}

}  // namespace dda::test
