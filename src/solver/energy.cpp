#include "solver/energy.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "kinematics/block_matrices.hpp"
#include "kinematics/frames.hpp"
#include "solver/configuration_update.hpp"
#include "solver/contact_assembly.hpp"

namespace dda {
namespace {

// The initial stress of a block in the global frame now (the local-frame treatments hold it
// in the block frame, where it turns with the block).
Vec3 initial_stress_now(const World& world, const Block& b) {
  return keeps_block_frame(world.control.rotation_update)
             ? stress_from_turned_frame(b.initial_stress, b.rotation)
             : b.initial_stress;
}

// Complementary energy density s : C^-1 : s / 2 of an isotropic elastic solid, for a stress
// (xx, yy, zz, xy) (Pa -> J/m^3).
double complementary_density(const Vec4& s, double young, double poisson) {
  const double normal = s[0] * s[0] + s[1] * s[1] + s[2] * s[2] -
                        2.0 * poisson * (s[0] * s[1] + s[1] * s[2] + s[2] * s[0]);
  return (normal + 2.0 * (1.0 + poisson) * s[3] * s[3]) / (2.0 * young);
}

// A contact's shear spring energy F^2 / 2 ks, locked or sliding (a sliding contact is its
// spring in series with the slider: ContactState::spring_energy); none when open.
double shear_spring_energy(const Contact& c, double ks) {
  if (c.state.mode == ContactMode::Open) return 0.0;
  const double f = c.iterate.shear_force;
  return f * f / (2.0 * ks);
}

// A contact's normal spring energy k/2 g^2 in `mode` at gap g: a closed spring is linear,
// so it holds it at either sign of g (a bonded contact in tension, g > 0, too); an open
// contact that penetrates (g < 0) holds it as well, and the next step's spring gives it back
// although no work put it there (the account then shows it).
double normal_spring_energy(ContactMode mode, double gap, double kn) {
  return mode != ContactMode::Open || gap < 0.0 ? 0.5 * kn * gap * gap : 0.0;
}

// A plastic block's stress with its out-of-plane component, (xx, yy, zz, xy).
Vec4 stress4(const Block& b) { return Vec4(b.stress[0], b.stress[1], b.szz, b.stress[2]); }

// A plastic block's stress and total strain in the frame its material integrates in: the
// block frame for the treatments that keep one (b.stress is global, turned by the block's
// angle), else the global frame.
Vec4 material_stress(const World& world, const Block& b) {
  if (!keeps_block_frame(world.control.rotation_update)) return stress4(b);
  const Vec3 s = stress_in_turned_frame(b.stress, b.rotation);
  return Vec4(s[0], s[1], b.szz, s[2]);
}
const Vec3& material_strain(const World& world, const Block& b) {
  return keeps_block_frame(world.control.rotation_update) ? b.local_strain : b.strain;
}

}  // namespace

double block_strain_energy(const World& world, const Block& b) {
  // Over the area the stress acts over (stress_area: the initial one under
  // finite_rotation_polar, whose stress is Kirchhoff's).
  const double area = stress_area(world.control.rotation_update, b);
  if (!b.plastic) return 0.5 * area * b.strain.dot(elastic_of(world, b) * b.strain);
  const Vec3 s0 = initial_stress_now(world, b);
  const Vec4 ds = stress4(b) - Vec4(s0[0], s0[1], initial_stress4(world, b)[2], s0[2]);
  const MaterialParameters& m = material_of(world, b);
  return area * complementary_density(ds, m.young, m.poisson);
}

double contact_energy(const World& world, const std::vector<Contact>& contacts, double penalty) {
  const double ks = kShearSpringRatio * penalty;
  double e = 0.0;
  for (const Contact& c : contacts) {
    // (An augmented contact's multiplier force p s is not a spring: its work is a term of
    // its own, multiplier_work.)
    e += normal_spring_energy(c.state.mode, c.iterate.new_gap, penalty);
    e += shear_spring_energy(c, ks);
  }
  for (const Pin& pin : world.pins) {
    if (world.blocks[static_cast<std::size_t>(pin.block)].fixed) continue;
    e += 0.5 * penalty * (pin.anchor - pin.current).squaredNorm();
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

StepEnergy step_energy(const World& world, const std::vector<Contact>& contacts,
                       const Eigen::VectorXd& d, const StepContext& ctx) {
  StepEnergy s;
  s.plastic_elastic_before.assign(world.blocks.size(), 0.0);
  s.plastic_stress_before.assign(world.blocks.size(), Vec4::Zero());
  s.plastic_strain_before.assign(world.blocks.size(), Vec3::Zero());
  s.plastic_area_before.assign(world.blocks.size(), 0.0);
  const double kn = ctx.penalty;
  const double ks = kShearSpringRatio * ctx.penalty;
  for (std::size_t i = 0; i < world.blocks.size(); ++i) {
    const Block& b = world.blocks[i];
    if (b.fixed) continue;
    const Vec6 db = d.segment<6>(b.first_dof);
    const Vec3 de = db.segment<3>(kEx);
    const double area = b.moments.area;
    const double stressed = stress_area(world.control.rotation_update, b);
    // Base shaking: the d'Alembert force -m a_ground of the ground's frame does work on the
    // block's translation (solver/base_motion.hpp); zero without it.
    s.load_work -= density_now(world, b) * area * ctx.base_acceleration.dot(db.head<2>());
    // Shi's step takes the stiffness at the end of the step (backward Euler on the strain):
    // the work of s_end on de falls short of the stored energy's rise by A/2 de^T D de.
    if (b.plastic) {
      s.plastic_elastic_before[i] = block_strain_energy(world, b);
      s.plastic_stress_before[i] = material_stress(world, b);
      s.plastic_strain_before[i] = material_strain(world, b);
      s.plastic_area_before[i] = stressed;
    } else {
      s.damping_dissipation += 0.5 * stressed * de.dot(elastic_of(world, b) * de);
    }
    s.load_work -= stressed * initial_stress_now(world, b).dot(de);
    // The dynamic coefficient k carries k v0 into the step: (1 - k^2) of the kinetic energy
    // is removed before the step starts.
    const double k = ctx.dynamic_coefficient;
    s.damping_dissipation += (1.0 - k * k) * kinetic_energy(world, b);
  }
  for (const Pin& pin : world.pins) {
    const Block& b = world.blocks[static_cast<std::size_t>(pin.block)];
    if (b.fixed) continue;
    const Mat26 tp = step_t(ctx, pin.block).at(pin.current - b.moments.centroid);
    s.damping_dissipation += 0.5 * ctx.penalty * (tp * d.segment<6>(b.first_dof)).squaredNorm();
  }
  // A constant force at a material point: its work on the point's motion (point loads and
  // joint water, both held over the step).
  auto point_force_work = [&](int index, const Vec2& at, const Vec2& force) {
    const Block& b = world.blocks[static_cast<std::size_t>(index)];
    if (b.fixed) return 0.0;
    const Mat26 tp = step_t(ctx, index).at(at - b.moments.centroid);
    return force.dot(tp * d.segment<6>(b.first_dof));
  };
  for (const PointLoad& load : world.loads) {
    s.load_work += point_force_work(load.block, load.current, load.force);
  }
  for (const BlockForce& w : world.water_forces) s.load_work += point_force_work(w.block, w.point, w.force);
  auto suspect = [&s](const Contact& c, double energy) {
    if (energy <= 0.0) return;
    s.suspects.push_back({c.key, energy});
    std::sort(s.suspects.begin(), s.suspects.end(),
              [](const auto& a, const auto& b) { return a.energy > b.energy; });
    if (s.suspects.size() > 3) s.suspects.pop_back();
  };
  for (const Contact& c : contacts) {
    if (c.state.mode == ContactMode::Open) continue;
    // The normal spring's force is taken at the step's end, -k g_end, over the whole step:
    // its work -k g_end (g_end - g_start) falls short of the rise of the stored energy by
    // what the scheme removes: k/2 (g_end - g_start)^2 for
    // a contact closed throughout, k/2 g_end^2 + k |g_end| g_start for one that closed
    // during the step from a gap g_start > 0 (the impact's loss). An augmented contact adds
    // the multiplier's force p s (ContactState::rest_shift), constant over the step; its work
    // on the blocks, p s (g_end - g_start), is multiplier_work.
    const double g0 = c.gap, g1 = c.iterate.new_gap;
    s.multiplier_work += kn * c.state.rest_shift * (g1 - g0);
    // What the spring held at the start is what contact_energy() booked at the last step's
    // end, by the same rule in the mode the contact started the step in. Counting only
    // penetration (min(g, 0)) lost k/2 g^2 a step from every contact held in tension.
    const ContactMode start_mode =
        c.iterate.mode_changes > 0 ? c.iterate.start_mode : c.state.mode;
    const double stored_start = normal_spring_energy(start_mode, g0, kn);
    s.damping_dissipation += kn * g1 * (g1 - g0) - (0.5 * kn * g1 * g1 - stored_start);
    double brought = stored_start;
    if (c.state.mode == ContactMode::Lock) {
      const double s_start = c.stretch_from(c.state.t_lock);
      const double s_end = -c.iterate.shear_force / ks;
      s.damping_dissipation += 0.5 * ks * (s_end - s_start) * (s_end - s_start);
      brought += 0.5 * ks * s_start * s_start;
    } else {
      // A sliding contact is its shear spring in series with the slider: of the friction's
      // work on the step's tangential motion, the part that changed the spring's energy
      // (F^2 / 2 ks now against what the contact held at the step's start, as a lock or a
      // slide) is stored, the rest dissipated. Without the spring a relock, which anchors
      // the spring where it keeps the friction the contact carried, would bring S^2 / 2 ks
      // from nowhere, and a release would lose it (docs/contacts.md, "Relocking").
      const double stored = shear_spring_energy(c, ks) - c.state.spring_energy;
      const double dissipated = -c.iterate.shear_force * c.iterate.slip - stored;
      s.friction_dissipation += std::max(0.0, dissipated);
      s.friction_gain += std::max(0.0, -dissipated);
      brought += std::max(0.0, -dissipated);
    }
    suspect(c, brought);
  }
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
  for (std::size_t i = 0; i < world.blocks.size(); ++i) {
    const Block& b = world.blocks[i];
    if (!b.plastic || b.fixed) continue;
    // The material's own account, in the frame it integrates in: the end stress (less the
    // initial stress, whose share load_work books) on the strain increment the step
    // committed, less the rise of elastic energy, is what plastic flow took plus the
    // backward-Euler share A/2 ds : C^-1 : ds (zero plastic work for a step that stays
    // elastic); the latter goes to damping. Read in the global frame instead, the
    // increment d[ex..] (turned into the block by the mid-step angle) and the global
    // stresses (turned by the start and end angles) booked a spinning block that never
    // yields 6 J of negative plastic work: the treatment's placement error, which belongs
    // to the remainder.
    const Vec4 stress = material_stress(world, b);
    const Vec3 de = material_strain(world, b) - step.plastic_strain_before[i];
    const Vec4 ds = stress - step.plastic_stress_before[i];
    const Vec3 s0 = b.initial_stress;
    const MaterialParameters& m = material_of(world, b);
    const double area = step.plastic_area_before[i];
    const double implicit = area * complementary_density(ds, m.young, m.poisson);
    led.damping_dissipation += implicit;
    // The energy density's rise over the start area (plastic_elastic_before is the start
    // area's energy), not the area's change.
    const double elastic_rise =
        area / stress_area(world.control.rotation_update, b) * block_strain_energy(world, b) -
        step.plastic_elastic_before[i];
    led.plastic_dissipation += area * (Vec3(stress[0], stress[1], stress[3]) - s0).dot(de) -
                               elastic_rise - implicit;
  }
  led.contact_energy = contact_energy(world, contacts, penalty);
  const EnergyTotals totals = scene_energy(world);
  led.remainder = totals.total() - led.initial_total - led.load_work - led.multiplier_work +
                  led.friction_dissipation +
                  led.plastic_dissipation + led.damping_dissipation;
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

void record_spring_energies(std::vector<Contact>& contacts, double penalty) {
  const double ks = kShearSpringRatio * penalty;
  for (Contact& c : contacts) c.state.spring_energy = shear_spring_energy(c, ks);
}

}  // namespace dda
