#include "solver/elements/pin_element.hpp"

#include "kinematics/block_matrices.hpp"

namespace dda {
namespace {

void assemble_pins(const World& world, const StepContext& ctx, BlockSystem& system) {
  for (const Pin& pin : world.pins) {
    const Block& b = world.blocks[pin.block];
    if (b.fixed) continue;  // a pin on a fixed block holds nothing that moves
    const Mat26 tp = step_t(ctx, pin.block).at(pin.current - b.moments.centroid);
    system.diagonal[block_row(b)] += spring_stiffness(tp, ctx.penalty);
    system.rhs.segment<6>(b.first_dof) += spring_force(tp, ctx.penalty, pin.anchor - pin.current);
  }
}

// The spring's force is taken at the step's end over the whole step (backward Euler): its
// work falls short of the stored energy's rise by p/2 |T d|^2.
void book_pins(const World& world, const Eigen::VectorXd& d, const StepContext& ctx,
               StepEnergy& s) {
  for (const Pin& pin : world.pins) {
    const Block& b = world.blocks[static_cast<std::size_t>(pin.block)];
    if (b.fixed) continue;
    const Mat26 tp = step_t(ctx, pin.block).at(pin.current - b.moments.centroid);
    s.damping_dissipation += 0.5 * ctx.penalty * (tp * d.segment<6>(b.first_dof)).squaredNorm();
  }
}

void add_pin_energy(const World& world, double penalty, double& e) {
  for (const Pin& pin : world.pins) {
    if (world.blocks[static_cast<std::size_t>(pin.block)].fixed) continue;
    e += 0.5 * penalty * (pin.anchor - pin.current).squaredNorm();
  }
}

}  // namespace

// Pins: a spring of the penalty's stiffness to each anchor.
const ForceElement kPinElement{assemble_pins, book_pins, add_pin_energy, nullptr, nullptr,
                               nullptr};

}  // namespace dda
