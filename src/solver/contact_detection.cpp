#include "solver/contact_detection.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "contact/broad_phase.hpp"
#include "contact/carry_over.hpp"
#include "contact/narrow_phase.hpp"

namespace dda {
namespace {

// The length of the face share this vertex carries (narrow_phase.hpp, face_shares): a point
// contact carries none, so no cohesion or tensile strength. With it, the rock bridge smeared
// over the faces it carries (Block::edge_bridges of the vertex's block, by the halves'
// lengths), so that a contact carries the bridge share of the face it stands for rather
// than of the whole edge it touches; a vertex whose faces have none takes the touched edge's.
struct ContactFace {
  double length = 0.0;
  int bridge_joint = -1;
  double bridge_share = 0.0;
};

ContactFace contact_face(const Block& vertex_block, int v, const Block& edge_block, int edge,
                         const EdgeFrame& frame) {
  const FaceShares shares = face_shares(vertex_block.vertices, v, frame.start, frame.end);
  ContactFace out;
  double bridged = 0.0;
  for (int k = 0; k < shares.count; ++k) {
    const auto i = static_cast<std::size_t>(k);
    const double length = shares.halves[i].norm();
    out.length += length;
    if (vertex_block.edge_bridges.empty()) continue;
    const BlockSpec::EdgeBridge& b = vertex_block.edge_bridges[static_cast<std::size_t>(shares.edges[i])];
    if (b.material < 0) continue;
    out.bridge_joint = b.material;
    bridged += b.share * length;
  }
  if (out.bridge_joint >= 0 && out.length > 0.0) {
    out.bridge_share = bridged / out.length;
  } else if (!edge_block.edge_bridges.empty()) {
    const BlockSpec::EdgeBridge& b = edge_block.edge_bridges[static_cast<std::size_t>(edge)];
    out.bridge_joint = b.material;
    out.bridge_share = b.share;
  }
  return out;
}

// `frame`: the frame of the candidate's edge, edge_frame(edge block's vertices, c.edge).
Contact make_contact(const World& world, const ContactCandidate& c, const EdgeFrame& frame) {
  const Polygon& vp = world.blocks[c.vertex_block].vertices;
  const EdgeProjection proj = project_on_edge(vp[c.vertex], frame);
  Contact k;
  k.key = {c.vertex_block, c.vertex, c.edge_block, c.edge};
  k.joint = joint_of_contact(world, c.vertex_block, c.edge_block, c.edge);
  k.vertex = vp[c.vertex];
  k.edge_start = frame.start;
  k.edge_end = frame.end;
  k.tangent = frame.tangent;
  k.normal = frame.normal;
  k.gap = proj.gap;
  // Not clamped to the edge: a vertex-to-vertex contact may project past the edge's end, and
  // its shear spring must be anchored where the vertex really is (a clamped anchor starts
  // the spring stretched by the overhang: a box of tumbling blocks gained 9 MJ/m that way).
  k.t = proj.t;
  const ContactFace face = contact_face(world.blocks[static_cast<std::size_t>(c.vertex_block)], c.vertex,
                                        world.blocks[static_cast<std::size_t>(c.edge_block)], c.edge, frame);
  k.length = face.length;
  k.bridge_joint = face.bridge_joint;
  k.bridge_share = face.bridge_share;
  k.allowed_penetration = contact_allowance(world, c.vertex_block, c.edge_block);
  return k;
}

// Both paths end here: `found` holds this step's contacts with fresh geometry; they take the
// state carried from `contacts` and replace them (`found` is left holding the old ones).
void carry_and_replace(const World& world, std::vector<Contact>& contacts,
                       std::vector<Contact>& found) {
  // Blocks placed face to face are "closed" although round-off may leave a gap of a few ulps.
  const double touching = 1e-9 * world.w0;
  carry_over(contacts, found, touching, world.step == 0, world.joint_laws);
  for (Contact& c : found) c.start_normal_force = c.state.normal_force;
  std::swap(contacts, found);
}

// A block's box grown by its share of the pair search distance (pair_search_distance): two
// grown boxes overlap when the blocks' boxes are within the pair's search distance.
Box search_box(const World& world, const Block& b) {
  return grown_box(b.vertices,
                   0.5 * (kSearchDistanceFactor * b.reach + world.allowed_penetration));
}

bool both_fixed(const World& world, int i, int j) {
  return world.blocks[i].fixed && world.blocks[j].fixed;  // nothing can move
}

// An excavated block is gone: it touches nothing and covers no face.
bool either_excavated(const World& world, int i, int j) {
  return world.blocks[i].excavated || world.blocks[j].excavated;
}

}  // namespace

void detect_contacts_full(const World& world, std::vector<Contact>& contacts) {
  std::vector<Box> boxes;
  boxes.reserve(world.blocks.size());
  for (const Block& b : world.blocks) boxes.push_back(search_box(world, b));

  std::vector<ContactCandidate> candidates;
  for (const auto& [i, j] : overlapping_pairs(boxes)) {
    if (both_fixed(world, i, j) || either_excavated(world, i, j)) continue;
    find_contacts(world.blocks[i].vertices, i, world.blocks[j].vertices, j,
                  pair_search_distance(world, i, j), candidates);
  }
  std::vector<Contact> found;
  found.reserve(candidates.size());
  for (const ContactCandidate& c : candidates) {
    const EdgeFrame frame = edge_frame(world.blocks[c.edge_block].vertices, c.edge);
    found.push_back(make_contact(world, c, frame));
  }
  carry_and_replace(world, contacts, found);
}

void detect_contacts(const World& world, std::vector<Contact>& contacts, DetectionCache& cache) {
  const std::size_t n = world.blocks.size();
  cache.boxes.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    cache.boxes[i] = search_box(world, world.blocks[i]);
  }
  carried_overlapping_pairs(cache.boxes, kCarriedPairMargin * world.search_distance, cache.pairs,
                            cache.close);

  // Each block's edge frames and vertex data once, not once per neighbour: a block whose
  // every pair is between fixed blocks needs none, but they cost little.
  cache.features.resize(n);
  for (std::size_t i = 0; i < n; ++i) polygon_features(world.blocks[i].vertices, cache.features[i]);
  // Blocks side by side: to a third block the faces they share are not surfaces
  // (mark_covered_edges). Firmly for two fixed blocks, whose faces must coincide; between
  // free blocks in contact (within their allowed penetration) the cover only steers the
  // vertex-pair rule, since the two may part (docs/contacts.md, "Covered faces").
  for (const auto& [i, j] : cache.close) {
    if (either_excavated(world, i, j)) continue;
    const bool firm = both_fixed(world, i, j);
    mark_covered_edges(cache.features[i], i, cache.features[j], j,
                       firm ? 0.0 : contact_allowance(world, i, j), firm);
  }

  cache.candidates.clear();
  for (const auto& [i, j] : cache.close) {
    if (both_fixed(world, i, j) || either_excavated(world, i, j)) continue;
    find_contacts(world.blocks[i].vertices, cache.features[i], i, world.blocks[j].vertices,
                  cache.features[j], j, pair_search_distance(world, i, j), cache.candidates);
  }
  cache.found.clear();
  cache.found.reserve(cache.candidates.size());
  for (const ContactCandidate& c : cache.candidates) {
    // The same frame edge_frame would make (polygon_features made it so).
    const PolygonFeatures& edges = cache.features[static_cast<std::size_t>(c.edge_block)];
    cache.found.push_back(make_contact(world, c, edges[static_cast<std::size_t>(c.edge)].edge));
  }
  carry_and_replace(world, contacts, cache.found);
}

void detect_contacts(const World& world, std::vector<Contact>& contacts) {
  DetectionCache cache;
  detect_contacts(world, contacts, cache);
}

}  // namespace dda
