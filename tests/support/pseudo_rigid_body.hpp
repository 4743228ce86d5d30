// The CVODE pseudo-rigid reference body (verification/reference) of a world's single block:
// its mass, area, material second moment, elastic constants and gravity, and its pin (with
// the world's penalty as the pin's stiffness) when the world has one.
#pragma once

#include "pseudo_rigid_reference.hpp"
#include "solver/configuration_update.hpp"
#include "solver/world.hpp"

namespace dda::test {

inline reference::PseudoRigidBody pseudo_rigid_body_of(
    const World& w, reference::ElasticLaw law = reference::ElasticLaw::Linear) {
  const Block& b = w.blocks[0];
  reference::PseudoRigidBody body;
  body.mass = material_of(w, b).density * b.initial_area;
  body.area = b.initial_area;
  body.inertia = b.material_inertia;
  body.elastic = elastic_of(w, b);
  body.gravity = w.gravity;
  body.law = law;
  if (!w.pins.empty()) {
    body.pinned = true;
    body.pin_offset = w.pins[0].initial - b.initial_centroid;
    body.anchor = w.pins[0].anchor;
    body.pin_stiffness = w.penalty;
  }
  return body;
}

}  // namespace dda::test
