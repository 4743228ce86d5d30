// The built-in default scene (what `dda run` runs without a scene file). The same text is in
// scenes/default.json; tests/io/test_scene_reader.cpp checks that the two stay identical.
//
// Geometry: the pendulum sweeps a disc of radius |(1.75, 0.25)| = 1.77 m about its pin at
// (0.25, 0.25), which stays above the fixed floor (top at y = -2). The octagon starts centred
// at (-3, 0) with velocity (1, 3) m/s and spin 2 rad/s, lands on the floor near x = -2 after
// about 1 s, bounces and rolls to the left (its spin wins over its speed), away from the
// pendulum.
#include "io/scene_reader.hpp"

namespace dda {

const std::string& default_scene_text() {
  static const std::string text = R"json(
{
  "description": "Built-in default scene: a 2 m x 0.5 m rock block pinned near its left end swings down as a pendulum, while a free regular octagon (circumradius 0.5 m) is thrown up and to the right, spinning, lands on a fixed floor 2 m below and rolls and slides on it (joint friction 30 degrees).",
  "gravity": [0.0, -9.81],
  "plane": "strain",
  "control": {
    "time_step": 0.005,
    "end_time": 3.0,
    "max_displacement_ratio": 0.05,
    "dynamic_coefficient": 1.0,
    "output_every": 10
  },
  "materials": {
    "rock": {"model": "elastic", "density": 2700.0, "young": 1.0e9, "poisson": 0.25}
  },
  "joint_materials": {
    "default": {"friction_angle": 30.0, "cohesion": 0.0, "tensile_strength": 0.0}
  },
  "blocks": [
    {
      "vertices": [[0.0, 0.0], [2.0, 0.0], [2.0, 0.5], [0.0, 0.5]],
      "material": "rock"
    },
    {
      "vertices": [
        [-2.5, 0.0],
        [-2.646446609406726, 0.3535533905932738],
        [-3.0, 0.5],
        [-3.353553390593274, 0.3535533905932738],
        [-3.5, 0.0],
        [-3.353553390593274, -0.3535533905932738],
        [-3.0, -0.5],
        [-2.646446609406726, -0.3535533905932738]
      ],
      "material": "rock",
      "velocity": [1.0, 3.0, 2.0]
    },
    {
      "vertices": [[-6.0, -3.0], [4.0, -3.0], [4.0, -2.0], [-6.0, -2.0]],
      "material": "rock",
      "fixed": true
    }
  ],
  "pins": [
    {"point": [0.25, 0.25]}
  ]
}
)json";
  return text;
}

}  // namespace dda
