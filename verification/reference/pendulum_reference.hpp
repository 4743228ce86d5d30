// Reference solution of the rigid pendulum by SUNDIALS CVODE, for verifying the DDA rotation
// treatments: their period and amplitude against a CVODE solution of the pendulum equation.
//
// Equation (per unit thickness, SI units):
//
//     I_p theta'' = -m g l sin(theta),   i.e.   theta'' = -omega0^2 sin(theta),
//
// Angle convention: theta (rad) is the angle of the line pivot -> centroid measured from the
// DOWNWARD vertical, counter-clockwise positive (the code's convention for rotations), so
// theta = 0 is the stable rest position and theta = pi the inverted one. omega = theta' (rad/s),
// counter-clockwise positive. In a scene with gravity (0, -g), a centroid at
// pivot + l (sin theta, -cos theta) has this theta.
//
// The integration uses CVODE's Adams method (non-stiff problem; orders up to 12) with a Newton
// iteration on a dense 2x2 analytic Jacobian, relative tolerance 1e-13 by default and absolute
// tolerances scaled to the motion (rtol times the amplitude for theta, times the largest angular
// speed for omega). Measured against the exact elliptic-integral period: rtol 1e-13 gives
// <= 1e-11 relative period error up to 170 degrees (rtol 1e-12: 8e-10 at 170 degrees), for about
// 20 percent more steps (some 200 steps, 0.3 ms, per period); at 1e-14 round-off takes over. Crossings (turning points, periods) are located by CVODE's root finding,
// not by sampling. Every CVODE failure is thrown as std::runtime_error naming the CVODE call
// and the return flag; bad arguments are thrown as std::invalid_argument.
#pragma once

#include <vector>

namespace dda {

// The pendulum. omega0_sq = m g l / I_p (1/s^2, > 0), with m the mass (kg per metre of
// thickness), g the gravity (m/s^2), l the pivot-to-centroid distance (m) and I_p the moment of
// inertia about the pivot (kg m^2 per metre of thickness), I_p = I_c + m l^2.
struct PendulumParams {
  double omega0_sq = 1.0;  // 1/s^2: the small-amplitude angular frequency squared
  double theta0 = 0.0;     // rad: initial angle from the downward vertical, counter-clockwise +
  double omega_init = 0.0; // rad/s: initial angular velocity, counter-clockwise +
};

// Builds the parameters from the physical quantities: mass (kg/m), gravity (m/s^2, magnitude),
// arm l (m, pivot to centroid), pivot_inertia I_p (kg m^2/m, about the pivot).
PendulumParams pendulum_params(double mass, double gravity, double arm, double pivot_inertia,
                               double theta0, double omega_init);

// Centroidal polar moment of inertia per unit mass, I_c / m (m^2), of a regular n-gon
// (n >= 3) with circumradius R (m): (R^2 / 6) (1 + 2 cos^2(pi / n)).
double ngon_centroidal_inertia_per_mass(int n, double circumradius);

struct PendulumSolverOptions {
  double rtol = 1e-13;         // CVODE relative tolerance, in [1e-15, 1e-3]
  long max_steps = 100000000;  // CVODE step limit per output call (a guard, not a budget)
};

// theta(t) and omega(t) at the requested times (s), which must be >= 0 and non-decreasing.
struct PendulumSamples {
  std::vector<double> time;   // s, as requested
  std::vector<double> theta;  // rad
  std::vector<double> omega;  // rad/s
};
PendulumSamples pendulum_sample(const PendulumParams& p, const std::vector<double>& times,
                                const PendulumSolverOptions& opt = {});

// The period (s). Swinging about the bottom (energy below the inverted position's): the time
// between two successive zero crossings of omega from negative to positive (both located by
// CVODE's root finding, so the initial state does not need to be a turning point). Going over
// the top: the time for theta to advance by one revolution, 2 pi. Throws std::invalid_argument
// for a state at rest at an equilibrium (no motion) or exactly on the separatrix (infinite
// period), and std::runtime_error when no period is completed within 1e4 small-amplitude periods.
double pendulum_period(const PendulumParams& p, const PendulumSolverOptions& opt = {});

// The turning points (omega = 0, either direction) in (0, duration], located by root finding.
// A turning point at t = 0 (start from rest) is not listed.
struct PendulumTurningPoint {
  double time;   // s
  double theta;  // rad
};
std::vector<PendulumTurningPoint> pendulum_turning_points(const PendulumParams& p, double duration,
                                                          const PendulumSolverOptions& opt = {});

// The amplitude, max |theta(t)| over [0, duration] (rad): the largest of |theta| at t = 0, at
// the turning points in (0, duration] and at t = duration.
double pendulum_amplitude(const PendulumParams& p, double duration,
                          const PendulumSolverOptions& opt = {});

}  // namespace dda
