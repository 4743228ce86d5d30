#include "cutting/model.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "cutting/block_labels.hpp"
#include "kinematics/polygon.hpp"

namespace dda {
namespace {

std::string block_material(const ModelSpec& model, const Polygon& block, double tol) {
  const Vec2 p = interior_point(block, tol);
  for (const RegionModel& region : model.regions) {
    if (!region.material.empty() && contains_point(region.polygon, p)) return region.material;
  }
  return model.material;
}

// How deep the block lies under the free surface: the least distance between its edges and
// the domain's edges not fixed (segments that do not cross: the least of the distances from
// each one's ends to the other).
double depth_under_free_surface(const ModelSpec& model, const Polygon& block) {
  const Polygon& d = model.domain;
  double least = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < d.size(); ++k) {
    if (is_fixed_edge(model, k)) continue;
    const Vec2& p = d[k];
    const Vec2& q = d[(k + 1) % d.size()];
    for (std::size_t i = 0; i < block.size(); ++i) {
      const Vec2& a = block[i];
      const Vec2& b = block[(i + 1) % block.size()];
      least = std::min({least, distance_to_segment(a, p, q), distance_to_segment(p, a, b),
                        distance_to_segment(q, a, b)});
    }
  }
  return least;
}

bool block_fixed(const ModelSpec& model, const Polygon& block, double tol) {
  const Polygon& d = model.domain;
  for (int i : model.fixed.edges) {
    const std::size_t k = static_cast<std::size_t>(i);
    if (has_edge_along(block, d[k], d[(k + 1) % d.size()], tol)) return true;
  }
  if (model.fixed.depth && depth_under_free_surface(model, block) >= *model.fixed.depth - tol) {
    return true;
  }
  return model.fixed.polygon && lies_within(block, *model.fixed.polygon, tol);
}

// Where two blocks meet: the middle of the longest stretch of boundary they share (edges of
// the one on edges of the other, within `tol` of each other's line). nullopt: no stretch.
std::optional<Vec2> shared_middle(const Polygon& a, const Polygon& b, double tol) {
  std::optional<Vec2> best;
  double longest = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const Vec2& p = a[i];
    const Vec2 pq = a[(i + 1) % a.size()] - p;
    const double l2 = pq.squaredNorm();
    if (!(l2 > 0.0)) continue;
    const double length = std::sqrt(l2);
    for (std::size_t j = 0; j < b.size(); ++j) {
      const Vec2& r = b[j];
      const Vec2& s = b[(j + 1) % b.size()];
      if (std::abs(cross(pq, r - p)) > tol * length || std::abs(cross(pq, s - p)) > tol * length) {
        continue;  // not on this edge's line
      }
      const double t0 = std::max(0.0, std::min((r - p).dot(pq), (s - p).dot(pq)) / l2);
      const double t1 = std::min(1.0, std::max((r - p).dot(pq), (s - p).dot(pq)) / l2);
      if ((t1 - t0) * length > longest) {
        longest = (t1 - t0) * length;
        best = p + 0.5 * (t0 + t1) * pq;
      }
    }
  }
  return best;
}

// The joint material of the segments of group `group` (model_segments' numbering).
const std::string& group_joint_material(const ModelSpec& model, int group) {
  static const std::string kDefault = kDefaultJointMaterial;
  if (group < 0) return kDefault;
  const std::size_t g = static_cast<std::size_t>(group);
  const std::size_t sets = model.joint_sets.size(), joints = model.joints.size();
  if (g < sets) return model.joint_sets[g].joint_material;
  if (g < sets + joints) return model.joints[g - sets].joint_material;
  // A rock bridge is of its set's joint, with the bridge's strength smeared over it
  // (CutModel::edge_bridges).
  return model.joint_sets[g - sets - joints].joint_material;
}

}  // namespace

double label_tolerance(const Polygon& domain) {
  const Box box = bounding_box(domain);
  return 1e-9 * (box.max - box.min).norm();
}

bool is_fixed_edge(const ModelSpec& model, std::size_t k) {
  return std::find(model.fixed.edges.begin(), model.fixed.edges.end(), static_cast<int>(k)) !=
         model.fixed.edges.end();
}

// splitmix64 (Steele, Lea and Flood 2014) of the seed advanced by k golden-ratio steps: one
// well-mixed 64-bit value per set, the same on every platform.
std::uint64_t joint_set_seed(std::uint64_t seed, std::size_t k) {
  std::uint64_t z = seed + (static_cast<std::uint64_t>(k) + 1) * 0x9E3779B97F4A7C15ULL;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}

std::vector<JointSegment> model_segments(const ModelSpec& model) {
  const Box box = bounding_box(model.domain);
  std::vector<JointSegment> segments;
  const std::size_t sets = model.joint_sets.size(), joints = model.joints.size();
  std::vector<JointSegment> bridges;
  for (std::size_t k = 0; k < sets; ++k) {
    const bool bridged = !model.joint_sets[k].bridge_material.empty();
    std::vector<JointSegment> set_bridges;
    std::vector<JointSegment> traces =
        joint_set_traces(model.joint_sets[k].traces, box.min, box.max,
                         joint_set_seed(model.seed, k), bridged ? &set_bridges : nullptr);
    for (JointSegment& t : traces) t.group = static_cast<int>(k);
    for (JointSegment& b : set_bridges) b.group = static_cast<int>(sets + joints + k);
    segments.insert(segments.end(), traces.begin(), traces.end());
    bridges.insert(bridges.end(), set_bridges.begin(), set_bridges.end());
  }
  for (std::size_t j = 0; j < joints; ++j) {
    const int group = static_cast<int>(sets + j);
    segments.push_back({model.joints[j].from, model.joints[j].to, group});
  }
  segments.insert(segments.end(), bridges.begin(), bridges.end());
  return segments;
}

CutModel cut_model(const ModelSpec& model) {
  CutModel out;
  out.cut = cut_domain(model.domain, model_segments(model), model.min_block_area);
  const double tol = label_tolerance(model.domain);
  for (const Polygon& block : out.cut.blocks) {
    out.materials.push_back(block_material(model, block, tol));
    out.fixed.push_back(block_fixed(model, block, tol));
  }
  // A region with a joint material gives it to the pairs whose shared boundary's middle
  // lies in it (the first such region in list order), whatever joints made the boundary.
  const bool joint_regions = std::any_of(model.regions.begin(), model.regions.end(),
                                         [](const RegionModel& r) { return !r.joint_material.empty(); });
  const auto region_joint_material = [&](const Vec2& p) -> const std::string* {
    for (const RegionModel& region : model.regions) {
      if (!region.joint_material.empty() && contains_point(region.polygon, p)) {
        return &region.joint_material;
      }
    }
    return nullptr;
  };
  for (const BlockAdjacency& pair : out.cut.adjacency) {
    std::string name = group_joint_material(model, pair.group);
    if (joint_regions) {
      const std::optional<Vec2> middle =
          shared_middle(out.cut.blocks[static_cast<std::size_t>(pair.a)],
                        out.cut.blocks[static_cast<std::size_t>(pair.b)], tol);
      if (const std::string* r = middle ? region_joint_material(*middle) : nullptr) name = *r;
    }
    if (name != kDefaultJointMaterial) out.joints.push_back({pair.a, pair.b, name});
  }
  // Each edge on a joint: that joint's material, or the region's its middle lies in; and the
  // share of it that is rock bridge, with the bridge's material.
  const int first_bridge = static_cast<int>(model.joint_sets.size() + model.joints.size());
  for (std::size_t i = 0; i < out.cut.blocks.size(); ++i) {
    const Polygon& block = out.cut.blocks[i];
    std::vector<std::string> names;
    std::vector<EdgeBridge> bridges;
    for (std::size_t k = 0; k < block.size(); ++k) {
      double total = 0.0, bridged = 0.0, longest_joint = 0.0, longest_bridge = 0.0;
      int joint = -1, bridge = -1;
      for (const auto& [group, length] : out.cut.edge_parts[i][k]) {
        total += length;
        if (group >= first_bridge) {
          bridged += length;
          if (length > longest_bridge) longest_bridge = length, bridge = group;
        } else if (group >= 0 && length > longest_joint) {
          longest_joint = length, joint = group;
        }
      }
      if (joint < 0) joint = bridge;  // wholly bridge: of its set's joint
      bridges.emplace_back();
      if (joint < 0) {
        names.emplace_back();
        continue;
      }
      const Vec2 middle = 0.5 * (block[k] + block[(k + 1) % block.size()]);
      const std::string* r = joint_regions ? region_joint_material(middle) : nullptr;
      names.push_back(r != nullptr ? *r : group_joint_material(model, joint));
      if (bridge >= 0 && total > 0.0) {
        const std::size_t set = static_cast<std::size_t>(bridge - first_bridge);
        bridges.back() = {model.joint_sets[set].bridge_material, bridged / total};
      }
    }
    out.edge_joint_materials.push_back(std::move(names));
    out.edge_bridges.push_back(std::move(bridges));
  }
  return out;
}

}  // namespace dda
