#include "solver/contact_detection.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "contact/broad_phase.hpp"
#include "contact/carry_over.hpp"
#include "contact/narrow_phase.hpp"

namespace dda {
namespace {


// The share of a face-to-face contact this vertex carries: half of each of its two edges
// that lies along the contact edge (within the entrance tolerance). A vertex meeting the edge
// at an angle (a point contact) carries no length, so no cohesion or tensile strength.
double contact_length(const Polygon& vp, int v, const Vec2& edge_normal) {
  const int n = static_cast<int>(vp.size());
  double length = 0.0;
  for (int w : {(v + n - 1) % n, (v + 1) % n}) {
    const Vec2 a = vp[w] - vp[v];
    if (std::abs(a.dot(edge_normal)) <= kWedgeTolerance * a.norm()) length += 0.5 * a.norm();
  }
  return length;
}

Contact make_contact(const World& world, const ContactCandidate& c) {
  const Polygon& vp = world.blocks[c.vertex_block].vertices;
  const Polygon& ep = world.blocks[c.edge_block].vertices;
  const EdgeFrame frame = edge_frame(ep, c.edge);
  const EdgeProjection proj = project_on_edge(vp[c.vertex], frame);
  Contact k;
  k.key = {c.vertex_block, c.vertex, c.edge_block, c.edge};
  k.joint = joint_of_pair(world, c.vertex_block, c.edge_block);
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
  k.length = contact_length(vp, c.vertex, frame.normal);
  return k;
}

}  // namespace

void detect_contacts(const World& world, std::vector<Contact>& contacts) {
  std::vector<Box> boxes;
  boxes.reserve(world.blocks.size());
  for (const Block& b : world.blocks) boxes.push_back(grown_box(b.vertices, 0.5 * world.search_distance));

  std::vector<ContactCandidate> candidates;
  for (const auto& [i, j] : overlapping_pairs(boxes)) {
    if (world.blocks[i].fixed && world.blocks[j].fixed) continue;  // nothing can move
    find_contacts(world.blocks[i].vertices, i, world.blocks[j].vertices, j, world.search_distance,
                  candidates);
  }

  // Blocks placed face to face are "closed" although round-off may leave a gap of a few ulps.
  const double touching = 1e-9 * world.w0;
  std::vector<Contact> found;
  found.reserve(candidates.size());
  for (const ContactCandidate& cand : candidates) found.push_back(make_contact(world, cand));
  carry_over(contacts, found, touching, world.step == 0, world.joint_laws);
  contacts = std::move(found);
}

}  // namespace dda
