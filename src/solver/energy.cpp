#include "solver/energy.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "solver/contact_assembly.hpp"
#include "solver/elements/block_element.hpp"
#include "solver/force_element.hpp"

namespace dda {

double contact_energy(const World& world, const std::vector<Contact>& contacts, double penalty) {
  double e = 0.0;
  add_contact_spring_energy(contacts, penalty, e);
  for (const ForceElement& element : force_elements()) {
    if (element.add_stored) element.add_stored(world, penalty, e);
  }
  return e;
}

EnergyTotals scene_energy(const World& world) {
  EnergyTotals e;
  for (const Block& b : world.blocks) {
    if (b.fixed) continue;
    const double mass = block_mass(world, b);
    e.kinetic += kinetic_energy(world, b);
    e.potential -= mass * world.gravity.dot(b.moments.centroid);
    e.strain_energy += block_strain_energy(world, b);
  }
  e.contact_energy = world.energy.contact_energy;
  return e;
}

void note_suspect(StepEnergy& s, const ContactKey& key, double energy) {
  if (energy <= 0.0) return;
  s.suspects.push_back({key, energy});
  std::sort(s.suspects.begin(), s.suspects.end(),
            [](const auto& a, const auto& b) { return a.energy > b.energy; });
  if (s.suspects.size() > 3) s.suspects.pop_back();
}

StepEnergy step_energy(const World& world, const std::vector<Contact>& contacts,
                       const Eigen::VectorXd& d, const StepContext& ctx) {
  StepEnergy s;
  for (const ForceElement& element : force_elements()) element.book_step(world, d, ctx, s);
  book_contact_step(contacts, ctx, s);
  return s;
}

void commit_step_energy(World& world, const StepEnergy& step, const std::vector<Contact>& contacts,
                        double penalty) {
  EnergyLedger& led = world.energy;
  led.load_work += step.load_work;
  led.multiplier_work += step.multiplier_work;
  led.friction_dissipation += step.friction_dissipation;
  led.damping_dissipation += step.damping_dissipation;
  led.friction_gain += step.friction_gain;
  book_plastic_blocks(world, step, led);
  if (step.plastic_work != 0.0) led.plastic_dissipation += step.plastic_work;
  led.contact_energy = contact_energy(world, contacts, penalty);
  const EnergyTotals totals = scene_energy(world);
  led.remainder = totals.total() - led.initial_total - led.load_work - led.multiplier_work +
                  led.friction_dissipation +
                  led.plastic_dissipation + led.damping_dissipation + led.excavation;
  led.scale = std::max({led.scale, totals.kinetic, std::abs(led.load_work)});
  if (led.remainder > led.remainder_max) {
    led.remainder_max = led.remainder;
    led.remainder_max_step = world.step;
  }
  if (led.remainder < led.remainder_min) {
    led.remainder_min = led.remainder;
    led.remainder_min_step = world.step;
  }
}

bool energy_lost_beyond(const EnergyLedger& led, double tolerance) {
  return led.remainder_min < -tolerance * led.scale;
}

std::string energy_loss_message(const World& world, double tolerance) {
  const EnergyLedger& led = world.energy;
  if (!(led.remainder < -tolerance * led.scale)) return {};
  std::ostringstream out;
  out << "step " << world.step << " (t = " << world.time << " s): the energy account shows "
      << -led.remainder << " J/m lost without a cause, " << -100.0 * led.remainder / led.scale
      << " % of the scene's energy scale " << led.scale << " J/m (control.energy_tolerance "
      << tolerance << "); no friction, plasticity or damping booked it, so the run dissipated "
         "energy it does not account for (control.energy_losses \"stop\")";
  return out.str();
}

std::string energy_guard_message(const World& world, const StepEnergy& step, double tolerance) {
  const EnergyLedger& led = world.energy;
  if (!(led.remainder > tolerance * led.scale)) return {};
  std::ostringstream out;
  out << "step " << world.step << " (t = " << world.time << " s): the energy account shows "
      << led.remainder << " J/m gained without a cause, " << 100.0 * led.remainder / led.scale
      << " % of the scene's energy scale " << led.scale << " J/m (control.energy_tolerance "
      << tolerance << "); the run created energy, so its results are not physical";
  if (!step.suspects.empty()) {
    out << ". Contacts that brought the most energy into this step:";
    for (const auto& sus : step.suspects) {
      out << " vertex " << sus.key.vertex << " of block " << sus.key.vertex_block << " on edge "
          << sus.key.edge << " of block " << sus.key.edge_block << " (" << sus.energy << " J/m);";
    }
  }
  return out.str();
}

void start_energy_account(World& world) {
  world.energy = EnergyLedger{};
  world.energy.contact_energy = contact_energy(world, {}, world.penalty);
  const EnergyTotals e = scene_energy(world);
  world.energy.initial_total = e.total();
  double reach = 0.0;  // work of gravity and loads over w0
  for (const Block& b : world.blocks) {
    if (!b.fixed) reach += block_mass(world, b) * world.gravity.norm() * world.w0;
  }
  for (const PointLoad& load : world.loads) {
    if (!world.blocks[static_cast<std::size_t>(load.block)].fixed) reach += load.force.norm() * world.w0;
  }
  // A scene at rest (no gravity, no loads, nothing moving or strained) had a scale of 0,
  // and its round-off (1.9e-23 J/m for a pinned bar) was "inf %" of it: the guard stopped
  // it at step 1. The floor: the strain energy the free blocks would hold at a strain of
  // 1e-6 (a microstrain, the resolution of a strain gauge), E A (1e-6)^2 / 2 each; far
  // above round-off (1e-4 J/m for a 1 m^2 block at E = 1e9 Pa, against 1e-23), far below
  // the scale of any scene that moves (m g w0 is 2.6e4 J/m for that block under gravity).
  double rest = 0.0;
  for (const Block& b : world.blocks) {
    if (b.fixed) continue;
    rest += 0.5 * material_of(world, b).young * b.moments.area * kRestScaleStrain *
            kRestScaleStrain;
  }
  world.energy.scale = std::max({e.kinetic + e.strain_energy + e.contact_energy, reach, rest});
}

}  // namespace dda
