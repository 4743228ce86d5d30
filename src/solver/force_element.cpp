#include "solver/force_element.hpp"

#include "solver/elements/block_element.hpp"
#include "solver/elements/bolt_element.hpp"
#include "solver/elements/pin_element.hpp"
#include "solver/elements/point_force_element.hpp"

namespace dda {

std::span<const ForceElement> force_elements() {
  // The order is the sums' order: assembly, work and stored energy are added up element by
  // element in it, so a change of order changes results in the last bits.
  static const ForceElement table[] = {kBlockElement, kPinElement, kPointForceElement,
                                       kBoltElement};
  return table;
}

void start_element_modes(const World& world, LoopTerms& terms) {
  for (const ForceElement& e : force_elements()) {
    if (e.start_modes) e.start_modes(world, terms);
  }
}

int follow_element_modes(const World& world, const Eigen::VectorXd& d, const StepContext& ctx,
                         LoopTerms& terms) {
  int changed = 0;
  for (const ForceElement& e : force_elements()) {
    if (e.follow_modes) changed += e.follow_modes(world, d, ctx, terms);
  }
  return changed;
}

void commit_elements(World& world, const Eigen::VectorXd& d, const StepContext& ctx) {
  for (const ForceElement& e : force_elements()) {
    if (e.commit) e.commit(world, d, ctx);
  }
}

}  // namespace dda
