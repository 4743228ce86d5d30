#include "solver/elements/block_element.hpp"

#include "kinematics/block_matrices.hpp"
#include "kinematics/frames.hpp"
#include "kinematics/rotating_inertia.hpp"
#include "solver/configuration_update.hpp"
#include "solver/rotation/treatment.hpp"

namespace dda {
namespace {

void add_block_terms(const World& world, int index, const StepContext& ctx, Mat6& k,
                     Eigen::Ref<Vec6> f) {
  const Block& b = world.blocks[static_cast<std::size_t>(index)];
  const LinearT& t = step_t(ctx, index);
  const double density = density_now(world, b);
  const Mat6 mass = mass_matrix(t, b.moments, density);
  const Vec6 v0 = ctx.dynamic_coefficient * b.velocity;
  k += (2.0 / (ctx.dt * ctx.dt)) * mass;
  // In the ground's frame under base shaking, gravity less the ground's acceleration.
  f += body_force(t, b.moments, density, world.gravity - ctx.base_acceleration) +
       (2.0 / ctx.dt) * (mass * v0);
  // The quadratic velocity terms of a deformable block's inertia in its rotating frame
  // (centripetal, Coriolis; kinematics/rotating_inertia.hpp), taken to the right-hand side.
  // Turned to the global frame at the step's start, where the step also holds the block's
  // stress (initial_stress_force below): a steady spin then balances with no shear in the
  // block frame (at the mid-step angle, half a step's turn, r0/2, would show as shear).
  const std::vector<Spin>* spins = loop_spins(ctx);
  if (spins != nullptr && !b.rigid) {
    const RotationUpdate treatment = world.control.rotation_update;
    const Spin& spin = (*spins)[static_cast<std::size_t>(index)];
    f -= spatial_increments(treatment, b)
             ? spatial_rotating_inertia_force(b.material_inertia, b.rotation,
                                              stretch_strain(treatment, b), spin)
             : rotating_inertia_force(b.material_inertia, b.rotation, b.local_strain, spin);
  }
  const std::vector<MaterialLinearization>* material_terms = loop_material_terms(ctx);
  if (b.plastic && material_terms != nullptr) {
    // Newton: the stress at increment de is taken as s + D_t (de - de_k) (the material
    // linearised at the last solution, solver/material_coupling.hpp).
    const MaterialLinearization& l = (*material_terms)[static_cast<std::size_t>(index)];
    const double area = stress_area(world.control.rotation_update, b);
    k.block<3, 3>(kEx, kEx) += area * l.tangent;
    f.segment<3>(kEx) -= area * (l.stress - l.tangent * l.strain_increment);
  } else if (!b.rigid) {
    // (The stress's area: stress_area, which only finite_rotation_polar changes.)
    Moments stressed = b.moments;
    stressed.area = stress_area(world.control.rotation_update, b);
    k += elastic_stiffness(stressed, elastic_of(world, b));
    f += initial_stress_force(stressed, b.stress);
  }
}

void assemble_blocks(const World& world, const StepContext& ctx, BlockSystem& system) {
  for (std::size_t i = 0; i < world.blocks.size(); ++i) {
    const Block& b = world.blocks[i];
    if (b.fixed) continue;
    const int row = block_row(b);
    add_block_terms(world, static_cast<int>(i), ctx, system.diagonal[row],
                    system.rhs.segment<6>(b.first_dof));
  }
}

// The initial stress of a block in the global frame now (the local-frame treatments hold it
// in the block frame, where it turns with the block).
Vec3 initial_stress_now(const World& world, const Block& b) {
  return treatment_of(world).keeps_frame()
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

// A plastic block's stress with its out-of-plane component, (xx, yy, zz, xy).
Vec4 stress4(const Block& b) { return Vec4(b.stress[0], b.stress[1], b.szz, b.stress[2]); }

// A plastic block's stress and total strain in the frame its material integrates in: the
// block frame for the treatments that keep one (b.stress is global, turned by the block's
// angle), else the global frame.
Vec4 material_stress(const World& world, const Block& b) {
  if (!treatment_of(world).keeps_frame()) return stress4(b);
  const Vec3 s = stress_in_turned_frame(b.stress, b.rotation);
  return Vec4(s[0], s[1], b.szz, s[2]);
}
const Vec3& material_strain(const World& world, const Block& b) {
  return treatment_of(world).keeps_frame() ? b.local_strain : b.strain;
}

void book_blocks(const World& world, const Eigen::VectorXd& d, const StepContext& ctx,
                 StepEnergy& s) {
  s.plastic_elastic_before.assign(world.blocks.size(), 0.0);
  s.plastic_stress_before.assign(world.blocks.size(), Vec4::Zero());
  s.plastic_strain_before.assign(world.blocks.size(), Vec3::Zero());
  s.plastic_area_before.assign(world.blocks.size(), 0.0);
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
}

}  // namespace

// The blocks' own terms: inertia, elasticity, weight, initial stress.
const ForceElement kBlockElement{assemble_blocks, book_blocks, nullptr, nullptr, nullptr,
                                 nullptr};

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

void book_plastic_blocks(const World& world, const StepEnergy& step, EnergyLedger& led) {
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
}

}  // namespace dda
