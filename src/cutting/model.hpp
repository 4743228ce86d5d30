// A rock-slope model: a domain, its joint sets and single joints, regions of
// other materials, what is fixed; and the blocks it is cut into, each with its material,
// fixed or not, with the joint material of every pair of neighbouring blocks.
// docs/model-format.md documents the file that io/model_reader turns into a ModelSpec.
// Plain data and pure functions; the names of materials are only carried, never checked here
// (the reader has checked them).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "cutting/cut_domain.hpp"
#include "cutting/joint_sets.hpp"
#include "kinematics/types.hpp"

namespace dda {

inline constexpr const char* kDefaultJointMaterial = "default";

struct JointSetModel {
  JointSetSpec traces;
  std::string joint_material = kDefaultJointMaterial;
  // The joint material of the rock bridges between the set's traces on a line (their intact
  // rock's cohesion and tensile strength, usually a brittle bond): with one, each line is cut
  // whole, its bridges joints of this material; empty, the bridges are not cut and the dead
  // ends they leave inside blocks are removed.
  std::string bridge_material;
};

struct SingleJointModel {
  Vec2 from = Vec2::Zero();
  Vec2 to = Vec2::Zero();
  std::string joint_material = kDefaultJointMaterial;
};

// A zone of the model: the material of the blocks in it (empty: not this region's to say),
// and the joint material of the joints in it (empty: the sets' and single joints' own).
struct RegionModel {
  Polygon polygon;
  std::string material;
  std::string joint_material;
};

// Blocks fixed in place: those with an edge on one of the domain's edges listed (edge i runs
// from vertex i to vertex i + 1), those lying wholly inside or on `polygon`, and those lying
// wholly deeper than `depth` (m) under the free surface (the domain's edges not listed).
// Any may be given; a block that meets one rule is fixed.
struct FixedModel {
  std::vector<int> edges;
  std::optional<Polygon> polygon;
  std::optional<double> depth;
};

struct ModelSpec {
  Polygon domain;  // counter-clockwise, simple
  std::vector<JointSetModel> joint_sets;
  std::uint64_t seed = 1;
  std::vector<SingleJointModel> joints;
  std::vector<RegionModel> regions;
  std::string material;  // of every block in no region
  FixedModel fixed;
  double min_block_area = 0.0;  // m^2
};

// Tolerance of the geometric labels (fixed by an edge or a polygon, a centroid on a block's
// boundary, the block a region or an excavation holds): 1e-9 of the domain's bounding-box
// diagonal. The blocks' corners are exact intersections rounded to doubles once (~1e-16
// relative), so a block edge on the domain's boundary is on it to far better than this, and
// no real block is this thin.
double label_tolerance(const Polygon& domain);

// Whether domain edge k (from vertex k to vertex k + 1) is listed in fixed.edges: a support,
// not part of the free surface.
bool is_fixed_edge(const ModelSpec& model, std::size_t k);

// The share of an edge that is intact rock bridge (0 to 1, by length) and the bridge's joint
// material.
struct EdgeBridge {
  std::string material;
  double share = 0.0;
};

// A pair of neighbouring blocks whose contacts use a joint material other than "default".
struct CutJoint {
  int a = 0;
  int b = 0;
  std::string joint_material;
};

struct CutModel {
  CutResult cut;                        // blocks, adjacency and the cut's counts
  std::vector<std::string> materials;   // per block
  std::vector<bool> fixed;              // per block
  std::vector<CutJoint> joints;         // pairs of a non-default joint material, by (a, b)
  // Per block, per edge: the joint material of the joint the edge lies on (by its set or
  // single joint, or the region its middle lies in); empty for an edge on no joint (the
  // domain's boundary, a hole bridge), whose contacts take their pair's. A contact takes the
  // material of the edge it lies on (docs/model-format.md, "Joint materials").
  std::vector<std::vector<std::string>> edge_joint_materials;
  // Per block, per edge: the rock bridge along it (BlockSpec::edge_bridges), share 0: none.
  std::vector<std::vector<EdgeBridge>> edge_bridges;
};

// The seed of joint set k's traces: the model's seed and k mixed (splitmix64), so that the
// sets draw independent streams and adding a set leaves the others' traces as they were.
std::uint64_t joint_set_seed(std::uint64_t seed, std::size_t k);

// Every trace of every set (group k for set k), every single joint (group S + j for joint j,
// S the number of sets), and the rock bridges of every set with a bridge_material (group
// S + J + k for set k's, J the number of single joints): the segments cut_domain cuts the
// domain by. A bridge overlapping another joint exactly (collinear) is the bridge there.
std::vector<JointSegment> model_segments(const ModelSpec& model);

// Cuts the model's domain and labels the blocks: material (regions, cutting/block_labels),
// fixed, and the joint material of each neighbouring pair from the group that made most of
// their shared length (BlockAdjacency). A single joint that coincides with a trace of a set
// along some length takes that length (the higher group).
CutModel cut_model(const ModelSpec& model);

}  // namespace dda
