// The Mohr-Coulomb joint law of a contact as a pure decision: given what the latest solve
// says about a contact, which mode it takes next (Shi 1988, open-close iteration).
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "contact/contact.hpp"

namespace dda {

// What a bonded contact does when its shear force reaches its strength.
enum class JointLawKind : std::uint8_t {
  // Shi's bond (1988): the bond breaks for good at the first failure, in tension or in
  // shear, and the contact keeps friction only. Two vertex contacts of one face carrying
  // unequal normal forces then fail one after the other, below the face's limit-equilibrium
  // strength (progressive failure).
  BrittleBond,
  // Coulomb slip (perfectly plastic, as UDEC's Coulomb slip joint model; Itasca, UDEC
  // Theory and Background, "Joint constitutive models"): a bonded contact that reaches
  // cohesion x length + tan(phi) N slides and keeps resisting with exactly that, cohesion
  // included, and locks again when its slip reverses; only a failure in tension breaks the
  // bond for good. This is the joint that limit-equilibrium analysis assumes.
  CoulombSlip,
};

// A contact's springs: the normal spring is the scene's penalty p, the shear spring Shi's
// usual p / 2.5 (Shi 1988; docs/contacts.md). Every assembly, response and energy of a
// contact takes its shear stiffness from here.
inline constexpr double kShearSpringRatio = 1.0 / 2.5;
inline double shear_stiffness(double penalty) { return kShearSpringRatio * penalty; }

struct JointLaw {
  double tan_phi = 0.0;           // tan(friction angle)
  double cohesion = 0.0;          // Pa
  double tensile_strength = 0.0;  // Pa
  JointLawKind kind = JointLawKind::BrittleBond;
  // Peak to residual (slip weakening): over the first `residual_slip` metres a contact
  // slides, tan(phi) and the cohesion fall linearly to these; 0: no weakening.
  double residual_tan_phi = 0.0;
  double residual_cohesion = 0.0;  // Pa
  double residual_slip = 0.0;      // m
  // Barton-Bandis (jcs > 0; Barton and Choubey 1977, Bandis et al. 1983): tan_phi is the
  // residual angle phi_r's, and a contact at normal stress sigma_n acts with friction
  // tan(phi_r + jrc log10(jcs / sigma_n)) (law_at_stress), divided by friction_divisor (a
  // strength-reduction trial's factor).
  double jrc = 0.0;
  double jcs = 0.0;  // Pa
  double friction_divisor = 1.0;
};

// The Barton-Bandis friction angle (degrees) at normal stress `sigma_n` (Pa, compression
// positive): phi_r + jrc log10(jcs / sigma_n), the logarithm at least 0 (at sigma_n >= jcs
// the joint's asperities are sheared off: phi_r) and the whole at most 70 degrees (Barton's
// bound for low stress, where the logarithm grows without bound; at sigma_n = 0 the bound).
double barton_bandis_angle(double phi_r_deg, double jrc, double jcs, double sigma_n);

// The law a contact of face length `length` (m) carrying normal force `normal_force` (N/m)
// acts with: a Barton-Bandis law's friction at sigma_n = normal_force / length (a point
// contact, of no length, at sigma_n = jcs: phi_r), as a plain Coulomb law; any other law as
// it is.
JointLaw law_at_stress(const JointLaw& law, double normal_force, double length);

// The law a contact that has slid `slip_sum` metres (ContactState::slip_sum) acts with: the
// law itself without weakening, else tan(phi) and the cohesion that far from peak towards
// residual (linear in the slip, residual from residual_slip on).
JointLaw law_at_slip(const JointLaw& law, double slip_sum);

// A joint whose trace is intact rock over `share` of its length (a rock bridge of law
// `bridge`): the joint's and the bridge's strengths in proportion to their lengths, as
// Jennings (1970) smears a joint of finite persistence (c = (1 - k) c_bridge + k c_joint,
// tan phi likewise, k the persistence = 1 - share); tensile strength and the residual
// strengths likewise. It acts as the bridge's law (its bond breaks as the intact rock's) once
// any share is bridge.
JointLaw bridged_law(const JointLaw& joint, const JointLaw& bridge, double share);

// The law contact c acts with from `laws` (a scene's, or a strength-reduction trial's): its
// joint's, with its rock bridge smeared in (bridged_law), before any slip weakening.
JointLaw contact_joint_law(const std::vector<JointLaw>& laws, const Contact& c);

// The law's name in scenes, summaries and reports: "brittle_bond" or "coulomb_slip".
const char* joint_law_name(JointLawKind kind);
// The law of a name, or nothing for a name that is not a law's.
std::optional<JointLawKind> joint_law_of_name(std::string_view name);

// The shear force (N per metre) a closed contact can carry at normal force `normal_force`
// (compression positive): tan(phi) N, plus cohesion x length while bonded (the brittle
// bond's strength before it breaks; the Coulomb slip joint's, sliding or not).
double shear_strength(const Contact& c, const JointLaw& law, double normal_force);

// The resistance of a sliding contact (N per metre): tan(phi) N, plus cohesion x length for
// a bonded Coulomb slip contact (a brittle bond never slides bonded).
double sliding_resistance(const Contact& c, const JointLaw& law, double normal_force);

// What the latest solve says about one contact.
struct ContactTrial {
  double new_gap = 0.0;       // normal gap after the increments (m), < 0 closed
  // Locked: the shear spring force on the vertex along the tangent (N). Open: the force a
  // shear spring anchored where the vertex stood at the step's start would carry after
  // this trial's slip (-ks slip); its sign says which way a closing frictionless contact slides.
  double shear_force = 0.0;
  double slip = 0.0;          // the step's relative tangential displacement along the tangent (m)
  double normal_force = 0.0;  // p * max(0, -new_gap) (N)
  double tension = 0.0;       // p * max(0, new_gap): what a bonded contact must carry (N)
  // A slip smaller than this (m) is round-off, not a reversal: without it a frictionless
  // contact at rest flips between sliding and locked forever.
  double slip_tolerance = 0.0;
  // A closed contact opens only when its gap exceeds this (m). Without the band, contacts
  // that carry almost nothing (a brick's side against its neighbour) chatter between open,
  // locked and sliding at nanometre gaps and the open-close loop never settles.
  double open_tolerance = 0.0;
};

struct ContactDecision {
  ContactMode mode = ContactMode::Open;
  int slide_sign = 0;
  bool bonded = false;
  bool relock = false;  // the shear spring's anchor must move to the vertex's present place
};

// Transition rules:
//  - bonded, Coulomb slip (JointLawKind::CoulombSlip): a tension > tensile_strength * length
//    breaks the bond for good (then as unbonded); otherwise the contact stays closed and
//    bonded, locked until |shear| > cohesion * length + tan_phi * N, then sliding against that
//    resistance until its slip reverses (as an unbonded closed contact, cohesion included);
//  - bonded, brittle bond: holds (locked) until tension > tensile_strength * length or
//    |shear| > cohesion * length + tan_phi * N; then the bond is broken for good and the
//    contact continues as an unbonded one (open if separated, sliding if closed);
//  - unbonded: an open contact closes when new_gap <= 0; a closed one opens when
//    new_gap > open_tolerance;
//  - unbonded, closed: an open contact locks (on a frictionless joint it enters sliding,
//    along the trial's slip); a locked one slides when
//    |shear| > tan_phi * N (towards the shear force's opposite, i.e. the slip); a sliding
//    one locks again when its slip turns against its sliding direction
//    by more than the slip tolerance.
ContactDecision decide_contact_mode(const Contact& c, const ContactTrial& trial,
                                    const JointLaw& law);

// Whether a contact that has already changed mode `c.mode_changes` times in this
// open-close loop may take the decision `next`. Up to `free_changes` changes, any; after
// that only a tightening one (open -> sliding or locked, sliding -> locked), a bond that
// breaks, or a locked contact that slides (its shear passed its strength: held locked,
// nothing would bound that shear). Tightening only, the loop ends on the side that cannot
// create energy: a contact held open while it penetrates hands the next step a compressed
// spring nobody loaded, and one held sliding while its slip reverses lets friction push
// forward, while a closed or locked spring is conservative and its energy is accounted. A
// contact that cycles lock -> slide -> lock runs the loop to its limit, and the step is cut.
bool change_allowed(const Contact& c, const ContactDecision& next, int free_changes);

// Whether the change c -> next that `trial` asks for lies within the contact resolution
// `resolution` (m): the solve went past the change's threshold by no more than that. A
// closing contact penetrates at most `resolution`; an opening one opens at most that; a
// locked one's shear spring (stiffness ks, N/m) is stretched past the friction limit by at
// most that; a sliding one's slip reversed by at most that. A bond that forms or breaks is
// never within it. Such a change need not hold up the open-close loop
// (contact/open_close_decision.hpp, kDeferShare).
bool change_within_resolution(const Contact& c, const ContactDecision& next,
                              const ContactTrial& trial, const JointLaw& law, double ks,
                              double resolution);

}  // namespace dda
