#include "solver/contact_newton.hpp"

#include <algorithm>
#include <cmath>

#include "contact/joint_law.hpp"
#include "solver/contact_assembly.hpp"
#include "solver/open_close_modes.hpp"
#include "solver/linear_solver.hpp"

namespace dda {
namespace {

// The contact resolution of the converged solver, as a share of the contact's allowed
// penetration: a response that differs from the mode a contact was solved with by no more
// than a spring force over this length (a gap or penetration this small, a shear this close
// to the strength) is converged. The open-close loop defers changes up to 1e-5 of the
// scene's allowance (kDeferShare). Here 1e-6 of the contact's own allowance (4e-4 of the
// smaller block's size): for a 0.25 m square at the hard cases' penalty, a force of
// 5e10 x 5e-11 m = 2.5 N, 0.15 % of its weight, so a contact that would hold a block by
// tension (a 0.1 m square hanging under a ceiling: its weight 265 N, 20 times the
// resolution) is a mismatch, never converged.
constexpr double kNewtonResolutionShare = 1e-6;
// A sliding contact whose friction was taken at a normal force within this share of its
// answer's is converged (the friction follows the iterate's normal force, a fixed point that
// converges linearly, about 3x a solve on a tumbling square). The accepted step keeps the
// friction it was solved with (ContactNewton::finish), so the energy account books the force
// that acted: the step's friction is within 1 % of tan(phi) N at its end, and it still
// opposes the slip. (Shi's open-close loop takes it at the last iteration's N, unchecked.)
constexpr double kStrengthShare = 1e-2;
// A sliding contact measures its gap at the edge point its slip takes it to (as the
// open-close loop does, ContactState::predicted_slip): once the contacts agree, a point
// whose distance from the answer's slip, times the edge block's turn and strain in the
// step, is more than this share of the allowed penetration (the error of the gap measured
// there) moves there and the step is solved again. Measured where the last step's slip took it instead, a slab
// sliding while it turns (the dominoes) had its gap linearised off by the slip's change
// times the turn, and the update placed its vertex where the next step's spring held
// energy no work had put there (0.34 % of the scale over 2 s).
constexpr double kMeasurePointShare = 1e-3;
// The line search stops when the work rate along the line is this share of its value at
// the iterate (a root to 0.1 %), or after kLineSearchEvaluations evaluations. It is
// piecewise linear in the step length, so regula falsi takes a few.
constexpr double kLineSearchShare = 1e-3;
constexpr int kLineSearchEvaluations = 40;

}  // namespace

ContactNewton::ContactNewton(const World& world, const std::vector<Contact>& contacts,
                             const StepContext& ctx)
    : kn_(ctx.penalty), ks_(shear_stiffness(ctx.penalty)) {
  start_.resize(contacts.size());
  solved_strength_.assign(contacts.size(), 0.0);
  solved_mode_.assign(contacts.size(), {ContactMode::Open, 0});
  held_open_.assign(contacts.size(), 0);
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    const Contact& c = contacts[i];
    Start& s = start_[i];
    s.mode = c.state.mode;
    switch (c.state.mode) {
      case ContactMode::Open: s.anchor = c.t; break;
      case ContactMode::Lock: s.anchor = c.state.t_lock; break;
      case ContactMode::Slide: {
        // The spring in series with the slider holds the friction the contact carried at
        // the last step's end, as the energy account booked it (ContactState::spring_energy).
        const double stretch = c.state.slide_sign * std::sqrt(2.0 * c.state.spring_energy / ks_);
        s.anchor = c.t_behind(stretch);
        break;
      }
    }
  }
  measure(world, contacts, ctx);
}

ContactSprings ContactNewton::springs_of(const Contact& c) const {
  return ContactSprings{kn_, ks_, c.state.rest_shift, c.state.bonded, c.length};
}

ContactNewton::Trial ContactNewton::trial_at(const World& world, const Contact& c, std::size_t i,
                                             const Eigen::VectorXd& d) const {
  Trial t;
  const Measures& m = measures_[i];
  t.gap = c.gap + evaluate(world, c, m.normal, d);
  t.stretch = c.stretch_from(start_[i].anchor) + evaluate(world, c, m.shear, d);
  t.response = contact_response(contact_law(world, c), springs_of(c), t.gap, t.stretch);
  return t;
}

void ContactNewton::measure(const World& world, const std::vector<Contact>& contacts,
                            const StepContext& ctx) {
  measures_.resize(contacts.size());
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    const Contact& c = contacts[i];
    Measures& m = measures_[i];
    m.normal = relative_along(world, ctx, c, c.measure_point(), c.normal);
    m.tangent = relative_along(world, ctx, c, c.measure_point(), c.tangent);
    m.shear = relative_along(world, ctx, c, c.edge_point(start_[i].anchor), c.tangent);
  }
}

int ContactNewton::follow_measure_points(const World& world, std::vector<Contact>& contacts,
                                         const StepContext& ctx, const Eigen::VectorXd& d) {
  int moved = 0;
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    Contact& c = contacts[i];
    if (c.state.mode != ContactMode::Slide) continue;
    c.iterate.slip = evaluate(world, c, measures_[i].tangent, d);
    const double next = predicted_slip(world, c);
    // Measuring at a point off by `shift` along the edge moves the edge block's displacement
    // there by the shift times the block's turn and strain in the step (its gradient).
    const Block& edge_block = world.blocks[static_cast<std::size_t>(c.key.edge_block)];
    double gradient = 0.0;
    if (!edge_block.fixed) {
      gradient = d.segment<4>(edge_block.first_dof + kR0).cwiseAbs().sum();
    }
    const double shift = std::abs(next - c.state.predicted_slip);
    if (shift * gradient <= kMeasurePointShare * c.allowed_penetration) continue;
    c.state.predicted_slip = next;
    ++moved;
  }
  if (moved > 0) measure(world, contacts, ctx);
  return moved;
}

void ContactNewton::start(const World& world, std::vector<Contact>& contacts,
                          const Eigen::VectorXd& d) const {
  std::vector<int> slid(contacts.size(), 0);  // the slide sign carried in, 0 if not sliding
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    if (contacts[i].state.mode == ContactMode::Slide) slid[i] = contacts[i].state.slide_sign;
  }
  set_responses(world, contacts, d, false);
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    Contact& c = contacts[i];
    if (slid[i] == 0 || c.state.mode == ContactMode::Open) continue;
    c.state.mode = ContactMode::Slide;
    c.state.slide_sign = slid[i];
    c.iterate.shear_force =
        -c.state.slide_sign * sliding_resistance(c, contact_law(world, c), c.state.normal_force);
  }
}

void ContactNewton::respond(const World& world, std::vector<Contact>& contacts,
                            const Eigen::VectorXd& d) const {
  set_responses(world, contacts, d, true);
}

void ContactNewton::set_responses(const World& world, std::vector<Contact>& contacts,
                                  const Eigen::VectorXd& d, bool reversal_locks) const {
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    Contact& c = contacts[i];
    const Trial t = trial_at(world, c, i, d);
    // A contact solved as sliding one way whose iterate slides the other way has passed the
    // whole elastic branch of its friction law in one solve (a resting block's side contact:
    // a friction of a hundred newtons moves a 170 kg square microns at dt 0.002 s, while its
    // spring's elastic range is nanometres). Its next solve takes the elastic branch between
    // the two, the spring (Shi's rule: a slide whose slip reverses locks); the response at
    // that answer then says whether it holds.
    const bool reversed = reversal_locks && c.state.mode == ContactMode::Slide &&
                          t.response.mode == ContactMode::Slide &&
                          t.response.slide_sign != c.state.slide_sign;
    c.state.t_lock = start_[i].anchor;
    c.iterate.new_gap = t.gap;
    if (held_open_[i]) {
      c.state.mode = ContactMode::Open;
      c.state.slide_sign = 0;
      c.state.normal_force = 0.0;
      c.iterate.shear_force = 0.0;
      continue;
    }
    c.state.mode = reversed ? ContactMode::Lock : t.response.mode;
    c.state.slide_sign = reversed ? 0 : t.response.slide_sign;
    c.state.normal_force = std::max(t.response.normal_force, 0.0);
    c.iterate.shear_force = t.response.shear_force;
  }
}

NewtonCheck ContactNewton::check(const World& world, const std::vector<Contact>& contacts,
                                 const Eigen::VectorXd& d_hat, bool friction_follows) {
  NewtonCheck out;
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    const Contact& c = contacts[i];
    if (held_open_[i]) {
      solved_strength_[i] = 0.0;
      solved_mode_[i] = {ContactMode::Open, 0};
      ++out.held_open;
      continue;
    }
    const double resolution = kNewtonResolutionShare * c.allowed_penetration;
    const Trial t = trial_at(world, c, i, d_hat);
    // The forces the solve gave this contact at d_hat, in the mode it was solved with.
    double normal = 0.0, shear = 0.0;
    if (c.state.mode != ContactMode::Open) normal = kn_ * (c.state.rest_shift - t.gap);
    if (c.state.mode == ContactMode::Lock) shear = -ks_ * t.stretch;
    solved_strength_[i] = 0.0;
    if (c.state.mode == ContactMode::Slide) {
      const double held = friction_follows ? std::max(0.0, kn_ * (c.state.rest_shift - t.gap))
                                           : c.state.normal_force;
      solved_strength_[i] = sliding_resistance(c, contact_law(world, c), held);
      shear = -c.state.slide_sign * solved_strength_[i];
    }
    solved_mode_[i] = {c.state.mode, c.state.slide_sign};
    double shear_difference = std::abs(t.response.shear_force - shear);
    const bool strength_only = c.state.mode == ContactMode::Slide &&
                               t.response.mode == ContactMode::Slide &&
                               t.response.slide_sign == c.state.slide_sign;
    if (strength_only) {
      // Still sliding the same way: only its strength followed the normal force (the
      // friction is taken at the iterate's N, a fixed point that converges linearly).
      shear_difference = std::max(0.0, shear_difference - kStrengthShare * t.response.strength);
    }
    const double share = std::max(std::abs(t.response.normal_force - normal) / kn_,
                                  shear_difference / ks_) /
                         resolution;
    out.largest_mismatch = std::max(out.largest_mismatch, share);
    if (share > 1.0) ++out.mismatched;
    if (std::abs(t.response.normal_force - normal) / kn_ > resolution) {
      ++out.normal_mismatched;
      if (c.state.mode != ContactMode::Open) ++out.normal_mismatched_closed;
    }
    if (c.state.mode == ContactMode::Open && t.gap < 0.0) {
      out.open_inside_energy += 0.5 * kn_ * t.gap * t.gap;
    }
  }
  return out;
}

int ContactNewton::hold_open_pulling(const World& world, const std::vector<Contact>& contacts,
                                     const Eigen::VectorXd& d_hat) {
  int held = 0;
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    const Contact& c = contacts[i];
    if (held_open_[i] || c.state.mode == ContactMode::Open || c.state.bonded) continue;
    const double resolution = kNewtonResolutionShare * c.allowed_penetration;
    const double solved = kn_ * (c.state.rest_shift - trial_at(world, c, i, d_hat).gap);
    if (solved >= -kn_ * resolution) continue;  // pushes, or pulls within the resolution
    held_open_[i] = 1;
    ++held;
  }
  return held;
}

bool ContactNewton::friction_coupling(const World& world, const std::vector<Contact>& contacts,
                                      const Eigen::VectorXd& d_hat,
                                      std::vector<RankOneTerm>& u, std::vector<RankOneTerm>& v,
                                      Eigen::VectorXd& residual) const {
  u.clear();
  v.clear();
  residual = Eigen::VectorXd::Zero(d_hat.size());
  const auto term = [&world](const Contact& c, const Measure& m, double scale) {
    RankOneTerm t;
    const Block& bv = world.blocks[static_cast<std::size_t>(c.key.vertex_block)];
    const Block& be = world.blocks[static_cast<std::size_t>(c.key.edge_block)];
    for (int k = 0; k < 6; ++k) {
      if (!bv.fixed) t.entries.emplace_back(bv.first_dof + k, scale * m.on_vertex_block[k]);
      if (!be.fixed) t.entries.emplace_back(be.first_dof + k, scale * m.on_edge_block[k]);
    }
    return t;
  };
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    const Contact& c = contacts[i];
    if (c.state.mode != ContactMode::Slide) continue;
    const JointLaw law = contact_law(world, c);
    if (law.tan_phi == 0.0) continue;
    const Measure& mn = measures_[i].normal;
    const Measure& mt = measures_[i].tangent;
    const double normal = kn_ * (c.state.rest_shift - c.gap - evaluate(world, c, mn, d_hat));
    const double change = -c.state.slide_sign * law.tan_phi * (normal - c.state.normal_force);
    const RankOneTerm ut = term(c, mt, -c.state.slide_sign * law.tan_phi * kn_);
    for (const auto& [k, value] : term(c, mt, change).entries) residual[k] += value;
    u.push_back(ut);
    v.push_back(term(c, mn, 1.0));
  }
  return !u.empty();
}


double ContactNewton::line_search(const World& world, const std::vector<Contact>& contacts,
                                  const BlockSystem& block_terms,
                                  const Eigen::VectorXd& d, const Eigen::VectorXd& d_hat) const {
  const Eigen::VectorXd step = d_hat - d;
  // Blocks: the work rate of their terms, linear in the step length a: lin + a quad.
  const Eigen::VectorXd sr = block_terms.reduce(step);
  const Eigen::VectorXd residual =
      multiply(block_terms, block_terms.reduce(d)) - block_terms.reduce(block_terms.rhs);
  const double lin = sr.dot(residual);
  const double quad = sr.dot(multiply(block_terms, sr));
  // Contacts: gap and stretch along the line, and their responses there.
  struct Line {
    double gap = 0.0, dgap = 0.0, stretch = 0.0, dstretch = 0.0;
    ContactSprings springs;
    JointLaw law;
  };
  std::vector<Line> lines;
  lines.reserve(contacts.size());
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    if (held_open_[i]) continue;  // pushes nothing anywhere on the line
    const Contact& c = contacts[i];
    const Measure& mn = measures_[i].normal;
    const double anchor = start_[i].anchor;
    const Measure& ms = measures_[i].shear;
    Line l;
    l.gap = c.gap + evaluate(world, c, mn, d);
    l.dgap = evaluate(world, c, mn, step);
    l.stretch = c.stretch_from(anchor) + evaluate(world, c, ms, d);
    l.dstretch = evaluate(world, c, ms, step);
    if (l.dgap == 0.0 && l.dstretch == 0.0) continue;
    l.springs = springs_of(c);
    l.law = contact_law(world, c);
    lines.push_back(l);
  }
  const auto rate = [&](double a) {
    double r = lin + a * quad;
    for (const Line& l : lines) {
      const ContactResponse resp =
          contact_response(l.law, l.springs, l.gap + a * l.dgap, l.stretch + a * l.dstretch);
      r -= resp.normal_force * l.dgap + resp.shear_force * l.dstretch;
    }
    return r;
  };
  const double r0 = rate(0.0);
  if (!(r0 < 0.0)) return 1.0;  // not a descent direction (friction's fixed point): take it whole
  double r1 = rate(1.0);
  if (r1 <= 0.0) return 1.0;
  // Illinois regula falsi on [lo, hi] with rate(lo) < 0 < rate(hi).
  double lo = 0.0, hi = 1.0, rlo = r0, rhi = r1;
  int side = 0;
  double a = 1.0;
  for (int k = 0; k < kLineSearchEvaluations; ++k) {
    a = (lo * rhi - hi * rlo) / (rhi - rlo);
    const double r = rate(a);
    if (std::abs(r) <= kLineSearchShare * std::abs(r0)) break;
    if (r < 0.0) {
      lo = a;
      rlo = r;
      if (side == -1) rhi *= 0.5;
      side = -1;
    } else {
      hi = a;
      rhi = r;
      if (side == 1) rlo *= 0.5;
      side = 1;
    }
  }
  return a;
}

int ContactNewton::break_bonds(const World& world, std::vector<Contact>& contacts,
                               const Eigen::VectorXd& d) const {
  int broken = 0;
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    Contact& c = contacts[i];
    if (!c.state.bonded) continue;
    if (trial_at(world, c, i, d).response.breaks) {
      c.state.bonded = false;
      ++broken;
    }
  }
  return broken;
}

void ContactNewton::finish_as_solved(const World& world, std::vector<Contact>& contacts,
                                     const Eigen::VectorXd& d_hat) const {
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    Contact& c = contacts[i];
    const Measures& m = measures_[i];
    c.iterate.new_gap = c.gap + evaluate(world, c, m.normal, d_hat);
    c.iterate.slip = evaluate(world, c, m.tangent, d_hat);
    const double stretch = c.stretch_from(start_[i].anchor) + evaluate(world, c, m.shear, d_hat);
    switch (c.state.mode) {
      case ContactMode::Open: c.iterate.shear_force = 0.0; break;
      case ContactMode::Lock: c.iterate.shear_force = -ks_ * stretch; break;
      case ContactMode::Slide: c.iterate.shear_force = -c.state.slide_sign * solved_strength_[i]; break;
    }
    if (c.state.mode != ContactMode::Open) {
      c.state.normal_force = std::max(0.0, kn_ * (c.state.rest_shift - c.iterate.new_gap));
    }
  }
  finish_bookkeeping(world, contacts);
}

void ContactNewton::finish(const World& world, std::vector<Contact>& contacts,
                           const Eigen::VectorXd& d) const {
  set_responses(world, contacts, d, false);
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    Contact& c = contacts[i];
    // Still sliding the way it was solved: the friction that acted (kStrengthShare).
    if (c.state.mode == ContactMode::Slide && solved_mode_[i].first == ContactMode::Slide &&
        solved_mode_[i].second == c.state.slide_sign) {
      c.iterate.shear_force = -c.state.slide_sign * solved_strength_[i];
    }
    c.iterate.slip = evaluate(world, c, measures_[i].tangent, d);
  }
  finish_bookkeeping(world, contacts);
}

void ContactNewton::finish_bookkeeping(const World& world, std::vector<Contact>& contacts) const {
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    Contact& c = contacts[i];
    c.iterate.start_mode = start_[i].mode;
    c.iterate.start_t_lock = start_[i].anchor;
    c.iterate.mode_changes = 1;  // the energy account reads the start mode
    c.state.deferred.reset();
    // The next step measures a sliding contact where this step's slip takes it.
    c.state.predicted_slip = predicted_slip(world, c);
    if (c.state.mode == ContactMode::Open) {
      c.state.rest_shift = 0.0;
      c.state.normal_force = 0.0;
      c.iterate.shear_force = 0.0;
    }
  }
}

}  // namespace dda
