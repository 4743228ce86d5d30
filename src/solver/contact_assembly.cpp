#include "solver/contact_assembly.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <unordered_map>

#include "contact/joint_law.hpp"
#include "kinematics/block_matrices.hpp"

namespace dda {
namespace {

Mat26 t_at(const World& w, const StepContext& ctx, int block, const Vec2& x) {
  return step_t(ctx, block).at(x - w.blocks[static_cast<std::size_t>(block)].moments.centroid);
}


// Adds the terms of the energy k/2 (g0 + m.d)^2 (and so the stiffness k m m^T and the
// force -k g0 m) to the system; fixed blocks carry no unknowns and are left out.
class ContactAssembler {
 public:
  ContactAssembler(const World& w, BlockSystem& s, std::size_t pairs) : world_(w), system_(s) {
    index_.reserve(pairs);
  }

  void add_spring(const Contact& c, const Measure& m, double k, double g0) {
    const Block& bv = world_.blocks[c.key.vertex_block];
    const Block& be = world_.blocks[c.key.edge_block];
    if (!bv.fixed) {
      system_.diagonal[block_row(bv)] += k * m.on_vertex_block * m.on_vertex_block.transpose();
      system_.rhs.segment<6>(bv.first_dof) -= k * g0 * m.on_vertex_block;
    }
    if (!be.fixed) {
      system_.diagonal[block_row(be)] += k * m.on_edge_block * m.on_edge_block.transpose();
      system_.rhs.segment<6>(be.first_dof) -= k * g0 * m.on_edge_block;
    }
    if (!bv.fixed && !be.fixed) {
      const bool vertex_row = bv.first_dof > be.first_dof;  // store below the diagonal
      const Mat6 k_ve = k * m.on_vertex_block * m.on_edge_block.transpose();
      coupling(block_row(bv), block_row(be)) += vertex_row ? k_ve : Mat6(k_ve.transpose());
    }
  }

  // A force `f` (N) with measure m: work f (m.d) -> force vector f m.
  void add_force(const Contact& c, const Measure& m, double f) {
    const Block& bv = world_.blocks[c.key.vertex_block];
    const Block& be = world_.blocks[c.key.edge_block];
    if (!bv.fixed) system_.rhs.segment<6>(bv.first_dof) += f * m.on_vertex_block;
    if (!be.fixed) system_.rhs.segment<6>(be.first_dof) += f * m.on_edge_block;
  }

  // Reserves the coupling block of two free blocks (kept even for open contacts, so that the
  // sparsity pattern, and CHOLMOD's analysis, stays the same through the open-close loop).
  void touch(const Contact& c) {
    const Block& bv = world_.blocks[c.key.vertex_block];
    const Block& be = world_.blocks[c.key.edge_block];
    if (!bv.fixed && !be.fixed) coupling(block_row(bv), block_row(be));
  }

 private:
  Mat6& coupling(int a, int b) {
    const int row = std::max(a, b), col = std::min(a, b);
    const std::uint64_t key = pair_key(row, col);
    // A pair's contacts follow each other in the list (detection finds them pair by pair),
    // so most look-ups are the last one's; the map is for the rest.
    if (key != last_key_) {
      const auto [it, inserted] = index_.try_emplace(key, system_.couplings.size());
      if (inserted) system_.couplings.push_back({row, col, Mat6::Zero()});
      last_key_ = key;
      last_index_ = it->second;
    }
    return system_.couplings[last_index_].k;
  }

  const World& world_;
  BlockSystem& system_;
  std::unordered_map<std::uint64_t, std::size_t> index_;
  std::uint64_t last_key_ = std::numeric_limits<std::uint64_t>::max();
  std::size_t last_index_ = 0;
};

Vec2 projection_point(const Contact& c) { return c.measure_point(); }

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

RankOneTerm rank_one(const World& w, const Contact& c, const Measure& m, double k) {
  RankOneTerm term;
  const double scale = std::sqrt(k);
  const Block& bv = w.blocks[c.key.vertex_block];
  const Block& be = w.blocks[c.key.edge_block];
  for (int i = 0; i < 6; ++i) {
    if (!bv.fixed) term.entries.emplace_back(bv.first_dof + i, scale * m.on_vertex_block[i]);
    if (!be.fixed) term.entries.emplace_back(be.first_dof + i, scale * m.on_edge_block[i]);
  }
  return term;
}

}  // namespace

Measure relative_along(const World& w, const StepContext& ctx, const Contact& c, const Vec2& x,
                       const Vec2& dir) {
  Measure m;
  m.on_vertex_block = t_at(w, ctx, c.key.vertex_block, c.vertex).transpose() * dir;
  m.on_edge_block = -(t_at(w, ctx, c.key.edge_block, x).transpose() * dir);
  return m;
}

double evaluate(const World& w, const Contact& c, const Measure& m, const Eigen::VectorXd& d) {
  double value = 0.0;
  const Block& bv = w.blocks[c.key.vertex_block];
  const Block& be = w.blocks[c.key.edge_block];
  if (!bv.fixed) value += m.on_vertex_block.dot(d.segment<6>(bv.first_dof));
  if (!be.fixed) value += m.on_edge_block.dot(d.segment<6>(be.first_dof));
  return value;
}

void contact_spring_terms(const World& world, const Contact& c, const StepContext& ctx,
                          std::vector<RankOneTerm>& out) {
  if (c.state.mode == ContactMode::Open) return;
  out.push_back(rank_one(world, c, relative_along(world, ctx, c, projection_point(c), c.normal), ctx.penalty));
  if (c.state.mode == ContactMode::Lock) {
    const Vec2 anchor = c.edge_point(c.state.t_lock);
    out.push_back(rank_one(world, c, relative_along(world, ctx, c, anchor, c.tangent),
                           shear_stiffness(ctx.penalty)));
  }
}

void add_contact_terms(const World& world, std::vector<Contact>& contacts,
                       const StepContext& ctx, BlockSystem& system) {
  ContactAssembler assembler(world, system, contacts.size());
  const double kn = ctx.penalty;
  const double ks = shear_stiffness(ctx.penalty);
  for (const Contact& c : contacts) {
    assembler.touch(c);
    if (c.state.mode == ContactMode::Open) continue;
    assembler.add_spring(c, relative_along(world, ctx, c, projection_point(c), c.normal), kn,
                         c.gap - c.state.rest_shift);
    if (c.state.mode == ContactMode::Lock) {
      const Vec2 anchor = c.edge_point(c.state.t_lock);
      assembler.add_spring(c, relative_along(world, ctx, c, anchor, c.tangent), ks,
                           c.tangent.dot(c.vertex - anchor));
    } else {
      // Sliding: friction tan(phi) N (and a Coulomb slip bond's cohesion) on the vertex,
      // against its slip direction.
      const double friction =
          sliding_resistance(c, contact_law(world, c), c.state.normal_force);
      assembler.add_force(c, relative_along(world, ctx, c, projection_point(c), c.tangent),
                          -c.state.slide_sign * friction);
    }
  }
}

int augment_multipliers(const World& world, std::vector<Contact>& contacts, double target_share,
                        const StepContext& ctx) {
  const auto mass = [&world](int i) {
    const Block& b = world.blocks[static_cast<std::size_t>(i)];
    return b.fixed ? std::numeric_limits<double>::infinity()
                   : density_now(world, b) * b.moments.area;  // the mass matrix's
  };
  int grown = 0;
  for (Contact& c : contacts) {
    const double excess = -c.iterate.new_gap - target_share * c.allowed_penetration;
    if (c.state.mode == ContactMode::Open || excess <= 0.0) continue;
    if (ctx.dynamic_coefficient > 0.0) {
      const double lighter = std::min(mass(c.key.vertex_block), mass(c.key.edge_block));
      if (ctx.penalty * ctx.dt * ctx.dt < 2.0 * lighter) continue;
    }
    c.state.rest_shift += excess;
    ++grown;
  }
  return grown;
}

void book_contact_step(const std::vector<Contact>& contacts, const StepContext& ctx,
                       StepEnergy& s) {
  const double kn = ctx.penalty;
  const double ks = shear_stiffness(ctx.penalty);
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
    note_suspect(s, c.key, brought);
  }
}

void add_contact_spring_energy(const std::vector<Contact>& contacts, double penalty, double& e) {
  const double ks = shear_stiffness(penalty);
  for (const Contact& c : contacts) {
    // (An augmented contact's multiplier force p s is not a spring: its work is a term of
    // its own, multiplier_work.)
    e += normal_spring_energy(c.state.mode, c.iterate.new_gap, penalty);
    e += shear_spring_energy(c, ks);
  }
}

void record_spring_energies(std::vector<Contact>& contacts, double penalty) {
  const double ks = shear_stiffness(penalty);
  for (Contact& c : contacts) c.state.spring_energy = shear_spring_energy(c, ks);
}

void record_slips(std::vector<Contact>& contacts) {
  for (Contact& c : contacts) {
    if (c.state.mode == ContactMode::Slide) c.state.slip_sum += std::abs(c.iterate.slip);
  }
}

double deepest_penetration_share(const std::vector<Contact>& contacts) {
  double deepest = 0.0;
  for (const Contact& c : contacts) {
    if (c.allowed_penetration > 0.0) deepest = std::max(deepest, -c.iterate.new_gap / c.allowed_penetration);
  }
  return deepest;
}

double max_penetration(const std::vector<Contact>& contacts) {
  // Open contacts count too: one held open by the chatter limit may have closed meanwhile.
  double deepest = 0.0;
  for (const Contact& c : contacts) deepest = std::max(deepest, -c.iterate.new_gap);
  return deepest;
}

}  // namespace dda
