// The converged contact solver (control.contact_solver "newton"; docs/contact-solver.md).
//
// With penalty springs, each step's frictional contact problem is to find the increments d
// at which the blocks' equations balance the contact forces, each contact answering its
// trial by the regularised Coulomb law of contact/contact_response.hpp. Shi's open-close
// loop solves it by an active-set iteration without a line search: it takes every solve
// whole, so contacts near a threshold send it back and forth (lock, slide, lock) and the
// step is cut. Here it is solved by a semismooth Newton method with a line search: the modes
// are read off the present iterate, the system assembled with them is solved (the same
// assembly and kept factor as the open-close loop), and the iterate moves towards that
// solution only as far as the contact forces keep doing work against the motion (the root
// of the directional derivative of the step's energy, piecewise linear along the line). For
// frictionless contacts that energy is convex and the method converges from any start; with
// friction the strengths follow the normal forces of the iterate (a fixed point that
// settles with the modes).
//
// A step has converged when the contacts' responses at the solved increments agree with the
// modes they were solved with, up to the contact resolution (a force of k x 1e-6 of the
// allowed penetration at a spring of stiffness k), together with the secant rotation and
// the plastic blocks' Newton (solver/step.cpp). Bonds break only on a converged step, then
// the step is solved again without them.
#pragma once

#include <Eigen/Dense>
#include <utility>
#include <vector>

#include "contact/contact.hpp"
#include "contact/contact_response.hpp"
#include "solver/block_system.hpp"
#include "solver/contact_assembly.hpp"
#include "solver/sparse_cholesky.hpp"
#include "solver/step_context.hpp"
#include "solver/world.hpp"

namespace dda {

// Contacts whose response at the solved increments differs from the mode they were solved
// with by more than the resolution.
struct NewtonCheck {
  int mismatched = 0;
  int normal_mismatched = 0;  // whose normal force differs (open against closed, or its gap)
  // Those of them solved closed (their solved force may pull, or push where the response
  // says open); the others were solved open and push nothing.
  int normal_mismatched_closed = 0;
  int held_open = 0;  // contacts held open (hold_open_pulling), which the counts leave out
  double largest_mismatch = 0.0;  // the largest force difference, as a share of k x resolution
  // The springs' energy k g^2 / 2 of contacts solved open whose vertex ends inside the edge's
  // block (g < 0): energy no force did work for, should the attempt be accepted so.
  double open_inside_energy = 0.0;
};

class ContactNewton {
 public:
  // At an attempt's start (contacts as they entered the step): where each contact's shear
  // spring is anchored for the step (a locked contact's anchor, a sliding one's behind the
  // vertex by the friction it carried, an open one's where the vertex is).
  ContactNewton(const World& world, const std::vector<Contact>& contacts, const StepContext& ctx);

  // How each contact sees the increments under the step's present T (its normal gap and
  // slip at the measure point, its shear spring's stretch at the anchor): again whenever T
  // changes (finite_rotation's secant columns).
  void measure(const World& world, const std::vector<Contact>& contacts, const StepContext& ctx);

  // Once the contacts agree at d: each sliding contact's measure point moves to where its
  // slip at d takes it (kMeasurePointShare), and the measures follow. Returns how many moved
  // (0: the step's gaps are measured where its vertices end).
  int follow_measure_points(const World& world, std::vector<Contact>& contacts,
                            const StepContext& ctx, const Eigen::VectorXd& d);

  // The modes an attempt starts from: every contact's response at the iterate d it starts
  // from (zero), except that a contact that slid at the last step's end and is still closed
  // keeps sliding the same way.
  // Its spring holds the friction it carried, so its response at d = 0 sits exactly on the
  // kink between lock and slide and reads as locked: a block sliding down an incline took
  // 2.9 solves a step to find its slide again (static steps 2.0; both 1.0 now), and a failing
  // slope with 2300 sliding contacts spent a whole solve on them at every step. (Both starts
  // converge; where the frictional problem has more than one answer they may pick different
  // ones: docs/contact-solver.md, the rockfall.)
  void start(const World& world, std::vector<Contact>& contacts, const Eigen::VectorXd& d) const;

  // Every contact takes its response at increments d: mode, slip direction, anchor and
  // forces, the fields the assembly reads (add_contact_terms).
  void respond(const World& world, std::vector<Contact>& contacts,
               const Eigen::VectorXd& d) const;

  // The sliding contacts' friction as a function of their normal force, for a Newton step
  // with the modes as they are: F = -sign (tan(phi) kn (rest_shift - g(d)) + cohesion) on
  // each, so the system's matrix gains sum_j u_j v_j^T (u_j = -sign tan(phi) kn m_t,
  // v_j = m_n; unsymmetric), and the answer d_hat of the system with the friction held at
  // the normal force of the iterate leaves the residual sum_j (F_j(d_hat) - F_j held) m_t.
  // Terms in six slots per block; false when no sliding contact has friction.
  bool friction_coupling(const World& world, const std::vector<Contact>& contacts,
                         const Eigen::VectorXd& d_hat, std::vector<RankOneTerm>& u, std::vector<RankOneTerm>& v,
                         Eigen::VectorXd& residual) const;

  // The responses at the solved increments d_hat against the modes the contacts hold now
  // (those they were solved with). `friction_follows`: the solve took the sliding contacts'
  // friction at d_hat's normal force (friction_coupling), not at the iterate's.
  NewtonCheck check(const World& world, const std::vector<Contact>& contacts,
                    const Eigen::VectorXd& d_hat, bool friction_follows);

  // A way out of a cycle whose contacts solved closed pull at d_hat (unbonded, their
  // response open): each of them is held open for the rest of the attempt, whatever its
  // response (its vertex may then end inside the edge's block: the overshoot and
  // penetration checks of the step judge how far). Contacts only leave the closed set this
  // way, so the modes cannot cycle through them again, and nothing pulls. Returns how many.
  int hold_open_pulling(const World& world, const std::vector<Contact>& contacts,
                        const Eigen::VectorXd& d_hat);

  // How far to move from d towards d_hat: the root in (0, 1] of the work rate of all forces
  // along the line (blocks: `block_terms`, the assembled terms without contacts; contacts:
  // their responses), 1 when the forces still oppose the motion at d_hat.
  double line_search(const World& world, const std::vector<Contact>& contacts,
                     const BlockSystem& block_terms,
                     const Eigen::VectorXd& d, const Eigen::VectorXd& d_hat) const;

  // The converged step's bonds that break at d (the response says so): unbonded for good.
  // Returns how many.
  int break_bonds(const World& world, std::vector<Contact>& contacts,
                  const Eigen::VectorXd& d) const;

  // The accepted step's contact states at d, as the rest of the step reads them (energy
  // account, penetration checks, carry-over): the responses, the step's slip, the mode the
  // contact started with, the measure point of the next step.
  void finish(const World& world, std::vector<Contact>& contacts,
              const Eigen::VectorXd& d) const;
  // The same for an attempt accepted before it converged, as Shi's code accepts one: the
  // states as they were solved (the modes the answer d_hat was solved with and their forces
  // there), so that the energy account books the forces that acted.
  void finish_as_solved(const World& world, std::vector<Contact>& contacts,
                        const Eigen::VectorXd& d_hat) const;

 private:
  struct Start {
    double anchor = 0.0;  // edge parameter of the shear spring's anchor over the step
    ContactMode mode = ContactMode::Open;
  };
  struct Trial {
    double gap = 0.0;
    double stretch = 0.0;
    ContactResponse response;
  };
  Trial trial_at(const World& world, const Contact& c, std::size_t i,
                 const Eigen::VectorXd& d) const;
  ContactSprings springs_of(const Contact& c) const;
  void finish_bookkeeping(const World& world, std::vector<Contact>& contacts) const;
  void set_responses(const World& world, std::vector<Contact>& contacts,
                     const Eigen::VectorXd& d, bool reversal_locks) const;

  std::vector<Start> start_;
  struct Measures {
    Measure normal;   // the gap, at the measure point
    Measure tangent;  // the slip, at the measure point
    Measure shear;    // the shear spring's stretch, at the anchor
  };
  std::vector<Measures> measures_;
  // What the last checked solve gave each contact: its mode and slip direction, and a
  // sliding one's friction strength (taken at the normal force of the iterate before).
  std::vector<double> solved_strength_;
  std::vector<char> held_open_;  // hold_open_pulling's contacts: open whatever their response
  std::vector<std::pair<ContactMode, int>> solved_mode_;
  double kn_ = 0.0;  // the normal spring (the penalty) and the shear spring (N/m)
  double ks_ = 0.0;
};

}  // namespace dda
