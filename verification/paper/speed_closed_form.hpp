// Speed against error beyond rotation: work-precision sweeps over dt for
// (a) a contact case with a closed form, a block sliding down an incline with friction,
//     d(t) = g (sin a - cos a tan phi) t^2 / 2;
// (b) a plastic case with a closed form, the plane-strain compression of a Mohr-Coulomb
//     specimen through its contacts, whose vertical stress levels off at
//     s1 = N s3 + 2 c sqrt(N), N = (1 + sin phi) / (1 - sin phi).
// Neither turns, so one rotation treatment (finite_rotation, the default) is enough.
#pragma once

#include <string>
#include <vector>

#include "options.hpp"
#include "treatments.hpp"

namespace dda::paper {

struct InclinePoint {
  double dt = 0.0;
  int steps = 0;
  RunResult result;            // wall_s: the fastest of the repetitions
  double distance = 0.0;       // m, travel of the centroid down the slope at kInclineTime
  double distance_ref = 0.0;   // m, the closed form acc t^2 / 2
  double rel_error = 0.0;      // |d - d_ref| / d_ref at kInclineTime
  double lag = 0.0;            // s, tau in d = acc (t - tau)^2 / 2, at kInclineTime
  double lag_end = 0.0;        // s, the same at the end (2 kInclineTime)
  double slide_acc = 0.0;      // m/s^2, from the travel between t and 2t
  double acc_rel_error = 0.0;  // |slide_acc - acc| / acc
  double order = 0.0;          // observed order of rel_error against the previous dt (NaN first)
  double omega_dt = 0.0;       // Omega = dt sqrt(2 p / m): the contact's stiffness against the step
};

struct PlasticPoint {
  double dt = 0.0;
  int steps = 0;
  RunResult result;
  double syy = 0.0, sxx = 0.0;   // Pa, the specimen's stresses at the end
  double height = 0.0;           // m, the specimen's height at the end
  double s1_present = 0.0;       // Pa, N P / h + 2 c sqrt(N): the closed form on the present height
  double error_present = 0.0;    // |-syy - s1_present| / strength
  double error_signed = 0.0;     // (-syy - s1_present) / strength
  double lag_term = 0.0;         // N P (v dt) / (h^2 strength): one step's shortening
  double inertia_term = 0.0;     // error_signed + lag_term: what the lag leaves
  double error_nominal = 0.0;    // |-syy - strength| / strength (s3 = P on the initial height)
  double yield_residual = 0.0;   // |-syy - (N (-sxx) + 2 c sqrt N)| / strength
  double eps_p = 0.0;            // the specimen's equivalent plastic strain at the end
  double order = 0.0;            // observed order of error_present (NaN first)
};

struct ClosedFormSpeed {
  std::vector<InclinePoint> incline;
  std::vector<PlasticPoint> plastic;
  double incline_acc = 0.0;    // m/s^2, the closed form's acceleration
  double incline_time = 0.0;   // s, where the distance error is measured (the run is twice it)
  double incline_penalty = 0.0;  // N/m, Shi's auto penalty of the incline scene
  double incline_mass = 0.0;     // kg per metre, the sliding block's
  double strength = 0.0;       // Pa, N s3 + 2 c sqrt(N) at s3 = P
  double push_rate = 0.0;      // m/s, the platen's pin
  double push_time = 0.0;      // s
};

ClosedFormSpeed run_closed_form_speed(const Options& opt);
void write_closed_form_speed_csv(const Options& opt, const ClosedFormSpeed& r);
std::string closed_form_speed_report(const Options& opt, const ClosedFormSpeed& r);

}  // namespace dda::paper
