#include "solver/contact_assembly.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <unordered_map>

#include "kinematics/block_matrices.hpp"

namespace dda {
namespace {

Mat26 t_at(const World& w, const StepContext& ctx, int block, const Vec2& x) {
  return step_t(ctx, block).at(x - w.blocks[static_cast<std::size_t>(block)].moments.centroid);
}


// Slips below this share of the allowed penetration count as no slip (round-off), and a
// closed contact opens only beyond kOpenToleranceShare of it (see
// ContactTrial::open_tolerance). A coarser slip tolerance was tried and not kept
// (docs/contacts.md, "Rules tried and not kept").
constexpr double kSlipToleranceShare = 1e-6;
constexpr double kOpenToleranceShare = 1e-6;
// A contact that has changed mode this many times in one open-close loop may from then on
// only tighten (open -> sliding -> locked; a lock past its strength still slides;
// docs/contacts.md, "Chatter"): such a contact
// chatters between states that differ by nanometres (a brick's side against its
// neighbour), and the loop would otherwise be cut for nothing.
constexpr int kFreeModeChanges = 2;
// A contact held closed may end in tension by up to this share of the allowed penetration
// (0.64 um in a 1.6 m scene): the nanometre chatter of a brick's side stays inside it, while
// a spring that pulls a vertex back across a gap it started with (a box of tumbling blocks
// gained 1.5 % of its energy scale so) is beyond it and cuts the step.
constexpr double kHeldTensionShare = 1e-3;
// The contact resolution, as a share of the allowed penetration: a change of mode that the
// latest solve asks for by no more than this (a penetration, a gap, a spring's stretch past
// the friction limit or a reversed slip this small) does not, on its own, make the
// open-close loop go on. When every change a solve asks for is that small, the step is
// accepted and those contacts start the next step in their new mode (ContactState::deferred;
// Shi's code and ntdda go further and never iterate on a change of shear mode). Without it
// the side contacts of a settled wall, which carry almost nothing, flip between open,
// locked and sliding at nanometre scales every step. What the accepted step gets wrong is
// bounded by the resolution delta: a contact left open that penetrates delta brings
// p delta^2 / 2 into the next step, a sliding one that reverses by delta lets friction push
// forward over delta, and a lock held past the friction limit stores at most (ks delta)^2 /
// 2 ks more (conservatively); the energy account shows them.
constexpr double kDeferShare = 1e-5;

// Adds the terms of the energy k/2 (g0 + m.d)^2 (and so the stiffness k m m^T and the
// force -k g0 m) to the system; fixed blocks carry no unknowns and are left out.
class ContactAssembler {
 public:
  ContactAssembler(const World& w, BlockSystem& s) : world_(w), system_(s) {}

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
    const auto [it, inserted] = index_.try_emplace(pair_key(row, col), system_.couplings.size());
    if (inserted) system_.couplings.push_back({row, col, Mat6::Zero()});
    return system_.couplings[it->second].k;
  }

  const World& world_;
  BlockSystem& system_;
  std::unordered_map<std::uint64_t, std::size_t> index_;
};

Vec2 projection_point(const Contact& c) { return c.measure_point(); }

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

// Where a contact that locks again within the open-close loop anchors its shear spring
// (docs/contacts.md, "Relocking"). What the accepted step will say is decided by the whole
// loop, so it starts from what the contact carried at the step's start: a contact that
// started locked keeps its anchor, its shear capped at its present strength (the return map
// of a spring the loop found past it); one that started sliding starts at the friction it
// carries (`slide_offset`, vertex minus anchor along the tangent); one that started open, at
// zero (Shi's lock on closing).
double relock_anchor(const World& world, const Contact& c, double slide_offset, double ks) {
  switch (c.iterate.start_mode) {
    case ContactMode::Open:
      return c.t;
    case ContactMode::Slide:
      return c.t_behind(slide_offset);
    case ContactMode::Lock: {
      const double stretch = c.stretch_from(c.iterate.start_t_lock);
      const double strength =
          shear_strength(c, world.joint_laws[c.joint], c.state.normal_force);
      return c.t_behind(std::clamp(ks * stretch, -strength, strength) / ks);
    }
  }
  return c.t;
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
                           kShearSpringRatio * ctx.penalty));
  }
}

void add_contact_terms(const World& world, std::vector<Contact>& contacts,
                       const StepContext& ctx, BlockSystem& system) {
  ContactAssembler assembler(world, system);
  const double kn = ctx.penalty;
  const double ks = kShearSpringRatio * ctx.penalty;
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
          sliding_resistance(c, world.joint_laws[c.joint], c.state.normal_force);
      assembler.add_force(c, relative_along(world, ctx, c, projection_point(c), c.tangent),
                          -c.state.slide_sign * friction);
    }
  }
}

ContactUpdate update_contact_modes(const World& world, std::vector<Contact>& contacts,
                                   const Eigen::VectorXd& d, const StepContext& ctx) {
  const double kn = ctx.penalty;
  const double ks = kShearSpringRatio * ctx.penalty;
  ContactUpdate result;
  const double tension_band = kHeldTensionShare * world.allowed_penetration;
  const double resolution = kDeferShare * world.allowed_penetration;
  // First every contact's decision on this solve, then (once it is known whether the loop
  // goes on) the changes.
  struct Pending {
    ContactDecision next;
    bool changes = false;
    bool deferrable = false;
    double lock_offset = 0.0;  // ModeChange::lock_offset
  };
  std::vector<Pending> pending(contacts.size());
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    Contact& c = contacts[i];
    const Vec2 p0 = projection_point(c);
    ContactTrial trial;
    trial.new_gap = c.gap + evaluate(world, c, relative_along(world, ctx, c, p0, c.normal), d);
    // The spring acts on the gap less the multiplier's shift (zero unless augmented); the
    // contact opens and closes by the geometric gap, so a shift never holds a gap open.
    const double spring_gap = trial.new_gap - c.state.rest_shift;
    trial.normal_force = kn * std::max(0.0, -spring_gap);
    trial.tension = kn * std::max(0.0, spring_gap);
    trial.slip = evaluate(world, c, relative_along(world, ctx, c, p0, c.tangent), d);
    trial.slip_tolerance = kSlipToleranceShare * world.allowed_penetration;
    trial.open_tolerance = kOpenToleranceShare * world.allowed_penetration;
    const JointLaw& law = world.joint_laws[c.joint];
    if (c.state.mode == ContactMode::Lock) {
      const Vec2 anchor = c.edge_point(c.state.t_lock);
      const double shear = c.tangent.dot(c.vertex - anchor) +
                           evaluate(world, c, relative_along(world, ctx, c, anchor, c.tangent), d);
      trial.shear_force = -ks * shear;
    } else if (c.state.mode == ContactMode::Open) {
      trial.shear_force = -ks * trial.slip;
    } else if (c.state.mode == ContactMode::Slide) {
      trial.shear_force = -c.state.slide_sign * sliding_resistance(c, law, c.state.normal_force);
    }
    const auto differs = [&c](const ContactDecision& next) {
      return next.mode != c.state.mode || next.slide_sign != c.state.slide_sign ||
             next.bonded != c.state.bonded;
    };
    ContactDecision next = decide_contact_mode(c, trial, law);
    bool changes = differs(next);
    const bool wants_to_open = changes && next.mode == ContactMode::Open;
    if (changes && !change_allowed(c, next, kFreeModeChanges) && wants_to_open) {
      // Held closed although it would open: it must still obey the closed contact's rules
      // (a sliding one whose slip reverses locks), else its friction pushes forward.
      ContactTrial closed = trial;
      closed.new_gap = std::min(trial.new_gap, 0.0);
      next = decide_contact_mode(c, closed, law);
      changes = differs(next);
    }
    Pending& p = pending[i];
    p.next = next;
    p.changes = changes && change_allowed(c, next, kFreeModeChanges);
    if (!p.changes && wants_to_open && trial.new_gap > tension_band) ++result.held_in_tension;
    p.deferrable = p.changes && change_within_resolution(c, next, trial, law, ks, resolution);
    // A sliding contact that locks starts its shear spring at the friction it carried in
    // this solve (trial.shear_force), not at zero: locked afresh, it would have to slip
    // S / ks again before carrying it, a slip per relock (docs/contacts.md, "Relocking").
    if (next.relock && c.state.mode == ContactMode::Slide) p.lock_offset = -trial.shear_force / ks;
    c.iterate.new_gap = trial.new_gap;
    c.iterate.slip = trial.slip;
    c.state.normal_force = trial.normal_force;
    c.iterate.shear_force = trial.shear_force;
  }
  // Changes within the resolution alone do not make the loop go on: if nothing else
  // changed, the step ends on this solve and those contacts start the next step in their
  // new mode; if the loop goes on anyway, they take it from the next iteration.
  int others = 0;
  for (const Pending& p : pending) others += p.changes && !p.deferrable ? 1 : 0;
  const bool defer = others == 0;
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    Contact& c = contacts[i];
    const Pending& p = pending[i];
    c.state.deferred.reset();
    if (p.changes && p.deferrable && defer) {
      c.state.deferred = ModeChange{p.next.mode, p.next.slide_sign, p.next.relock, p.lock_offset};
    } else if (p.changes) {
      if (!p.deferrable) ++result.changed;
      if (c.iterate.mode_changes == 0) {
        c.iterate.start_mode = c.state.mode;
        c.iterate.start_t_lock = c.state.t_lock;
      }
      ++c.iterate.mode_changes;
      c.state.mode = p.next.mode;
      c.state.slide_sign = p.next.slide_sign;
      c.state.bonded = p.next.bonded;
      if (p.next.relock) c.state.t_lock = relock_anchor(world, c, p.lock_offset, ks);
    }
    // A sliding contact's normal spring moves to where the vertex now slides to (see
    // ContactState::predicted_slip); the next iteration measures there.
    c.state.predicted_slip = predicted_slip(world, c);
    // (A held contact keeps its mode, but its forces follow the latest solve.)
    if (c.state.mode == ContactMode::Open) {
      c.state.rest_shift = 0.0;
      c.state.normal_force = 0.0;
      c.iterate.shear_force = 0.0;
    }
  }
  return result;
}

double predicted_slip(const World& world, const Contact& c) {
  if (c.state.mode != ContactMode::Slide) return 0.0;
  // Bounded by what the two blocks may move this step: an iteration far from the solution
  // must not carry the measure point off the edge; a larger slip is cut by the displacement
  // check.
  const double reach = world.blocks[static_cast<std::size_t>(c.key.vertex_block)].reach +
                       world.blocks[static_cast<std::size_t>(c.key.edge_block)].reach;
  return std::clamp(c.iterate.slip, -reach, reach);
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
