// The scene's random strengths (docs/scene-format.md, "random_strengths"): which joint or
// block material properties, or the water table's fill, `dda fos --samples` draws at random,
// from which distribution, and which pairs are correlated. Plain data; the drawing is studies/random_strengths.hpp.
#pragma once

#include <limits>
#include <string>
#include <vector>

namespace dda {

enum class StrengthOwner { JointMaterial, Material, Water };
// WaterFill: the water table's share of the way from its dry line up to its phreatic line
// (WaterTable::fill), owned by the scene's water (index 0).
enum class StrengthProperty { FrictionAngle, Cohesion, TensileStrength, WaterFill };
enum class StrengthDistribution { Normal, Lognormal };

// One random variable. `mean` and `standard_deviation` are those of the variable itself
// (not of its logarithm for a lognormal one), in the property's units (degrees, Pa, a share).
// Draws outside [min, max] are drawn again: the reader has intersected the user's bounds
// with the property's valid range (friction angle [0, 90) degrees, strengths >= 0).
struct RandomStrength {
  StrengthOwner owner = StrengthOwner::JointMaterial;
  int index = 0;     // into Scene::joint_materials or Scene::materials; 0 for the water
  std::string name;  // the owner's name, for reports
  StrengthProperty property = StrengthProperty::FrictionAngle;
  StrengthDistribution distribution = StrengthDistribution::Normal;
  double mean = 0.0;
  double standard_deviation = 0.0;  // > 0
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
};

// A correlation coefficient between the standard normals behind two variables (for a
// lognormal variable, the normal of its logarithm). Each variable is in at most one pair.
struct StrengthCorrelation {
  int first = 0;   // indices into RandomStrengths::variables, first < second
  int second = 0;
  double coefficient = 0.0;  // (-1, 1)
};

struct RandomStrengths {
  std::vector<RandomStrength> variables;  // empty: the scene has none
  std::vector<StrengthCorrelation> correlations;
};

// The names the scene file uses: "friction_angle", "cohesion", "tensile_strength", "fill".
inline const char* strength_property_name(StrengthProperty p) {
  switch (p) {
    case StrengthProperty::FrictionAngle: return "friction_angle";
    case StrengthProperty::Cohesion: return "cohesion";
    case StrengthProperty::TensileStrength: return "tensile_strength";
    case StrengthProperty::WaterFill: return "fill";
  }
  return "?";
}
// "normal", "lognormal".
inline const char* strength_distribution_name(StrengthDistribution d) {
  return d == StrengthDistribution::Normal ? "normal" : "lognormal";
}

// What the scene file calls the owner: "joint_material", "material", "water".
inline const char* strength_owner_name(StrengthOwner o) {
  switch (o) {
    case StrengthOwner::JointMaterial: return "joint_material";
    case StrengthOwner::Material: return "material";
    case StrengthOwner::Water: return "water";
  }
  return "?";
}

}  // namespace dda
