#include "speed_closed_form.hpp"

#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>

#include "csv.hpp"
#include "paper_scenes.hpp"
#include "solver/moving_anchors.hpp"

namespace dda::paper {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// As the spinning block and the pendulum: the fastest of five identical runs is the wall time;
// a run of more than 50 ms is timed once (the scheduler's noise is small against it).
constexpr int kRepeats = 5;
constexpr double kTimedOnce = 0.05;  // s

// (a) The distance error is measured at 1 s (d = 0.906 m at 30 / 20 degrees) and the run goes
// on to 2 s, so that the travel between the two gives the sliding acceleration on its own.
constexpr double kInclineTime = 1.0;
const std::vector<double> kInclineSteps{0.02, 0.01, 0.005, 0.002, 0.001, 0.0005, 0.0002, 0.0001};
const std::vector<double> kInclineStepsSmoke{0.01, 0.005};

// (b) The platen's pin goes down at 1 mm/s for 2 s: a vertical strain of 2e-3, three times
// what the specimen needs to yield (~6e-4), so the last half of the push is on the plateau.
constexpr double kPushRate = 1e-3;
constexpr double kPushTime = 2.0;
const std::vector<double> kPlasticSteps{0.04, 0.02, 0.01, 0.005, 0.0025};
const std::vector<double> kPlasticStepsSmoke{0.02, 0.01};

int steps_for(double duration, double dt) { return static_cast<int>(std::lround(duration / dt)); }

double order_of(double e, double e_prev, double dt, double dt_prev) {
  if (!(e > 0.0) || !(e_prev > 0.0)) return kNaN;
  return std::log(e_prev / e) / std::log(dt_prev / dt);
}

double incline_acceleration() {
  const double a = kInclineSlope * kPi / 180.0;
  return kGravity * (std::sin(a) - std::cos(a) * std::tan(kInclineFriction * kPi / 180.0));
}

InclinePoint incline_once(double dt) {
  InclinePoint p;
  p.dt = dt;
  p.steps = steps_for(2.0 * kInclineTime, dt);
  const double a = kInclineSlope * kPi / 180.0;
  const Vec2 down(-std::cos(a), -std::sin(a));
  World world = make_world(incline_scene(dt, 2.0 * kInclineTime));
  const Vec2 start = world.blocks.back().moments.centroid;
  double t1 = kNaN;
  p.result = run_world(world, [&](const World& w) {
    if (std::isnan(t1) && w.time >= kInclineTime - 1e-9) {
      p.distance = (w.blocks.back().moments.centroid - start).dot(down);
      t1 = w.time;
    }
  });
  const double acc = incline_acceleration();
  const double d_end = (world.blocks.back().moments.centroid - start).dot(down);
  p.distance_ref = 0.5 * acc * kInclineTime * kInclineTime;
  p.rel_error = std::abs(p.distance - p.distance_ref) / p.distance_ref;
  p.lag = t1 - std::sqrt(2.0 * p.distance / acc);
  p.lag_end = world.time - std::sqrt(2.0 * d_end / acc);
  // (sqrt d2 - sqrt d1) = sqrt(acc / 2) (t2 - t1) whatever the lag.
  p.slide_acc = 2.0 * std::pow((std::sqrt(d_end) - std::sqrt(p.distance)) / (world.time - t1), 2);
  p.acc_rel_error = std::abs(p.slide_acc - acc) / acc;
  const Block& b = world.blocks.back();
  p.omega_dt = dt * std::sqrt(2.0 * world.penalty / (material_of(world, b).density * b.moments.area));
  return p;
}

double strength_of() {
  const double s = std::sin(kPlatenFriction * kPi / 180.0);
  const double n = (1.0 + s) / (1.0 - s);
  return n * kPlatenConfining + 2.0 * kPlatenCohesion * std::sqrt(n);
}

PlasticPoint plastic_once(double dt) {
  PlasticPoint p;
  p.dt = dt;
  p.steps = steps_for(kPushTime, dt);
  World world = make_world(platen_scene(dt, p.steps));
  // The platen's pin pushes it down at kPushRate (solver/moving_anchors.hpp).
  p.result = run_world(world, RunHook{{}, moving_anchors(Vec2(0.0, -kPushRate * dt)), {}});
  const Block& b = world.blocks[1];
  const double s = std::sin(kPlatenFriction * kPi / 180.0);
  const double n = (1.0 + s) / (1.0 - s), two_c_root_n = 2.0 * kPlatenCohesion * std::sqrt(n);
  const double strength = strength_of();
  p.syy = b.stress[1];
  p.sxx = b.stress[0];
  p.height = 0.5 * (b.vertices[3].y() - b.vertices[0].y() + b.vertices[2].y() - b.vertices[1].y());
  p.s1_present = n * kPlatenConfining / p.height + two_c_root_n;
  p.error_signed = (-p.syy - p.s1_present) / strength;
  p.error_present = std::abs(p.error_signed);
  p.lag_term = n * kPlatenConfining * kPushRate * dt / (p.height * p.height) / strength;
  p.inertia_term = p.error_signed + p.lag_term;
  p.error_nominal = std::abs(-p.syy - strength) / strength;
  p.yield_residual = std::abs(-p.syy - (n * -p.sxx + two_c_root_n)) / strength;
  p.eps_p = b.material_state.eps_p;
  return p;
}

// The fastest of `repeats` identical (deterministic) runs is the wall time.
template <class Point, class Once>
Point fastest(Once once, double dt, int repeats) {
  Point best = once(dt);
  for (int i = 1; i < repeats && best.result.status == RunStatus::Completed &&
                  best.result.wall_s < kTimedOnce;
       ++i) {
    best.result.wall_s = std::min(best.result.wall_s, once(dt).result.wall_s);
  }
  return best;
}

std::string order_text(double order) { return std::isnan(order) ? "-" : fixed(order, 2); }

}  // namespace

ClosedFormSpeed run_closed_form_speed(const Options& opt) {
  ClosedFormSpeed out;
  out.incline_acc = incline_acceleration();
  out.incline_time = kInclineTime;
  {
    const World w = make_world(incline_scene(0.01, 1.0));
    out.incline_penalty = w.penalty;
    out.incline_mass = material_of(w, w.blocks.back()).density * w.blocks.back().moments.area;
  }
  out.strength = strength_of();
  out.push_rate = kPushRate;
  out.push_time = kPushTime;
  const int repeats = opt.smoke ? 1 : kRepeats;
  for (double dt : opt.smoke ? kInclineStepsSmoke : kInclineSteps) {
    InclinePoint p = fastest<InclinePoint>(incline_once, dt, repeats);
    p.order = out.incline.empty() ? kNaN
                                  : order_of(p.rel_error, out.incline.back().rel_error, dt,
                                             out.incline.back().dt);
    out.incline.push_back(p);
  }
  for (double dt : opt.smoke ? kPlasticStepsSmoke : kPlasticSteps) {
    PlasticPoint p = fastest<PlasticPoint>(plastic_once, dt, repeats);
    p.order = out.plastic.empty() ? kNaN
                                  : order_of(p.error_present, out.plastic.back().error_present,
                                             dt, out.plastic.back().dt);
    out.plastic.push_back(p);
  }
  return out;
}

void write_closed_form_speed_csv(const Options& opt, const ClosedFormSpeed& r) {
  WholeFile inc = open_csv(opt.out, "speed_incline.csv",
                           "dt,steps,status,wall_s,distance,distance_ref,rel_error,order,"
                           "lag,lag_over_dt,lag_end,slide_acc,acc_ref,acc_rel_error,"
                           "omega_dt,penalty,mass,open_close_iterations,cut_steps");
  for (const InclinePoint& p : r.incline) {
    inc << full(p.dt) << ',' << p.steps << ',' << status_word(p.result.status) << ','
        << full(p.result.wall_s) << ',' << full(p.distance) << ',' << full(p.distance_ref) << ','
        << full(p.rel_error) << ',' << full(p.order) << ',' << full(p.lag) << ','
        << full(p.lag / p.dt) << ',' << full(p.lag_end) << ',' << full(p.slide_acc) << ','
        << full(r.incline_acc) << ',' << full(p.acc_rel_error) << ',' << full(p.omega_dt) << ','
        << full(r.incline_penalty) << ',' << full(r.incline_mass) << ','
        << p.result.stats.iterations << ',' << p.result.stats.cut_steps << '\n';
  }
  inc.finish();
  WholeFile pl = open_csv(opt.out, "speed_plastic.csv",
                          "dt,steps,status,wall_s,syy,sxx,height,s1_present,strength,"
                          "error_present,order,error_signed,lag_term,inertia_term,error_nominal,"
                          "yield_residual,eps_p,solves");
  for (const PlasticPoint& p : r.plastic) {
    pl << full(p.dt) << ',' << p.steps << ',' << status_word(p.result.status) << ','
       << full(p.result.wall_s) << ',' << full(p.syy) << ',' << full(p.sxx) << ','
       << full(p.height) << ',' << full(p.s1_present) << ',' << full(r.strength) << ','
       << full(p.error_present) << ',' << full(p.order) << ',' << full(p.error_signed) << ','
       << full(p.lag_term) << ',' << full(p.inertia_term) << ',' << full(p.error_nominal) << ','
       << full(p.yield_residual) << ',' << full(p.eps_p) << ',' << p.result.stats.iterations
       << '\n';
  }
  pl.finish();
}

std::string closed_form_speed_report(const Options& opt, const ClosedFormSpeed& r) {
  std::ostringstream md;
  md << "### A block sliding down an incline (speed_incline.png)\n\n"
     << "A " << kInclineBlock[0] << " m x " << kInclineBlock[1] << " m block (paper material) "
        "on a fixed " << kInclineSlope << " degree slope, joint friction " << kInclineFriction
     << " degrees, Shi's auto penalty, released from rest; closed form d(t) = g (sin a - cos a "
        "tan phi) t^2 / 2 with acceleration " << fixed(r.incline_acc, 6) << " m/s^2, d("
     << fixed(r.incline_time, 0) << " s) = " << fixed(0.5 * r.incline_acc * r.incline_time *
                                                      r.incline_time, 6)
     << " m. The run goes on to " << fixed(2.0 * r.incline_time, 0)
     << " s; the error is that of the distance at " << fixed(r.incline_time, 0)
     << " s, the observed order log(e_prev / e) / log(dt_prev / dt) against the previous dt; "
        "the lag tau solves d = acc (t - tau)^2 / 2, and the sliding acceleration comes from "
        "the travel between the two times, (sqrt d2 - sqrt d1)^2 = acc (t2 - t1)^2 / 2, which "
        "is blind to the lag. Wall time: the fastest of " << (opt.smoke ? 1 : kRepeats)
     << " identical runs (a run of more than 50 ms timed once); default treatment "
        "(finite_rotation; the block does not turn).\n\n"
     << "| dt (s) | Omega | steps | wall (ms) | d(1 s) (m) | error | order | lag / dt | "
        "acceleration error | run |\n|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|\n";
  for (const InclinePoint& p : r.incline) {
    md << "| " << sig(p.dt) << " | " << sig(p.omega_dt) << " | " << p.steps << " | "
       << sig(1e3 * p.result.wall_s) << " | " << fixed(p.distance, 6) << " | " << sig(p.rel_error) << " | " << order_text(p.order)
       << " | " << fixed(p.lag / p.dt, 3) << " | " << sig(p.acc_rel_error) << " | "
       << describe(p.result) << " |\n";
  }
  const double omega = std::sqrt(2.0 * r.incline_penalty / r.incline_mass);
  const double a = kInclineSlope * kPi / 180.0;
  const double deficit = kGravity * std::cos(a) * std::tan(kInclineFriction * kPi / 180.0);
  md << "\nOmega = dt sqrt(2 p / m) is the step against the period of the block on its two "
        "corner springs (auto penalty p = " << sig(r.incline_penalty) << " N/m, m = "
     << sig(r.incline_mass) << " kg/m: omega = " << sig(omega)
     << " rad/s). Shi's step moves a body under a constant force by exactly v dt + a dt^2 / 2, "
        "so once the block slides its acceleration is the closed form's (the acceleration "
        "error stays below 1e-6 at every dt, the trace of the block's elastic compliance "
        "m g / E in positions that travel metres). The whole distance error is the start: "
        "the block stands on unloaded contact springs, and friction, tan phi times their "
        "force, follows them as they load, so the block leaves with a lag tau. Three "
        "regimes: (1) Omega >> 1 (dt >= 5 ms): the springs load within the first step, "
        "which is lost, tau = dt (0.95 to 1.0 dt), the error 2 dt / t, first order; "
        "(2) Omega ~ 5 to 25 (0.5 to 2 ms): the springs load within the step more and "
        "more, tau / dt falls towards 0 and the error drops faster than dt; (3) Omega ~ 1 "
        "to 2 (0.2 ms and less): the step resolves the springs' oscillation, which the "
        "scheme then damps only by about Omega / 4 a cycle, for about 4 / (omega^2 dt) s; "
        "while it lasts friction follows the oscillating normal force, and the block leaves "
        "up to g cos a tan phi x 4 / (omega^2 dt) / acc ahead or behind (here "
        << sig(deficit * 4.0 / (omega * omega * 1e-4) / r.incline_acc)
     << " s at dt = 1e-4 s), a floor of the penalty model's own start (the rigid block of "
        "the closed form has none), which a smaller dt does not lower (5e-4 of d here). The "
        "1e-5 at 0.5 ms is tau passing through zero on its way from +dt to the floor's "
        "negative values: luck, not a resolution to count on. Conclusion: with Omega >> 1 "
        "the error is 2 dt / t whatever the penalty (2e-2 at dt = 10 ms for under a "
        "millisecond of wall time); dt = 1 ms (Omega ~ 10) reaches the floor, 4e-4 for "
        "about 10 ms; a finer dt costs more and buys nothing.\n\n";
  md << "### A Mohr-Coulomb specimen compressed through its contacts (speed_plastic.png)\n\n"
     << "A unit-square Mohr-Coulomb specimen (c = " << sig(kPlatenCohesion) << " Pa, phi = psi = "
     << kPlatenFriction << " degrees, E = 1e10 Pa, nu = 0.25) between a fixed base and a "
        "stiff platen, frictionless joints, no gravity, confined by point loads P = "
     << sig(kPlatenConfining) << " N/m at mid-height of its sides, and pushed down through a "
        "pin at the platen's top at " << sig(r.push_rate) << " m/s for "
     << fixed(r.push_time, 0) << " s (static analysis; the step is a load step of "
     << sig(r.push_rate) << " dt m). Closed form: the plane-strain biaxial strength s1 = N "
        "s3 + 2 c sqrt(N), N = (1 + sin phi) / (1 - sin phi), = " << sig(r.strength, 6)
     << " Pa at s3 = P / 1 m. Because the confining loads are forces, s3 = P / h on the "
        "specimen's present height h, which the push shortens: the table gives the error "
        "against s1 on the present height (the scheme's error; its observed order) and "
        "against the nominal strength (what a user comparing with the textbook value sees), "
        "both relative to the strength, at the end of the push.\n\n"
     << "| dt (s) | steps | wall (ms) | -syy (Pa) | error (present h) | order | signed | "
        "lag term | remainder x dt (s) | error (nominal) | on the yield surface | solves | "
        "run |\n|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|\n";
  for (const PlasticPoint& p : r.plastic) {
    md << "| " << sig(p.dt) << " | " << p.steps << " | " << sig(1e3 * p.result.wall_s) << " | "
       << sig(-p.syy, 9) << " | " << sig(p.error_present) << " | " << order_text(p.order)
       << " | " << sig(p.error_signed) << " | " << sig(p.lag_term) << " | "
       << sig(p.inertia_term * p.dt) << " | " << sig(p.error_nominal) << " | " << sig(p.yield_residual) << " | "
       << p.result.stats.iterations << " | " << describe(p.result) << " |\n";
  }
  md << "\nThe return puts the stress on the yield surface to round-off at every dt, so the "
        "error on the present height is all equilibrium, and two terms make it. (1) The step "
        "writes equilibrium on the configuration at its start, so sxx lags one step's "
        "shortening, P (v dt) / h^2, and s1 N times that: the lag term N P v dt / (h^2 s1), "
        "known in advance, first order in dt, and negative (s1 short). (2) Static analysis "
        "keeps 2 M / dt^2 in the step and drops the velocities, so the mass resists each "
        "step's movement v dt with 2 M v / dt, a remainder of the other sign that grows as "
        "1 / dt: remainder x dt is the same at every dt (the column; its size is the "
        "specimen's lateral mass against P). The lag dominates at these light blocks "
        "(20 kg/m^3) down to dt ~ 3 ms, where the two cancel; below that the remainder "
        "takes over (at 2.5 ms the error has changed sign) and grows as 1 / dt. The error against the nominal strength is the shortening's own, N P (1 / h - "
        "1) / s1, the same at every dt (8.4e-4 to 8.6e-4): no step makes it smaller. "
        "Conclusion: for the strength a textbook compares with, the coarsest dt (50 load "
        "steps, under a millisecond) is as good as any (8.4e-4, the geometry's); against the "
        "closed form on the present height, dt = 0.01 s gives 4e-6 in ~2.5 ms and each "
        "halving of dt halves the error for twice the cost until the 1 / dt remainder takes "
        "over.\n\n";
  return md.str();
}

}  // namespace dda::paper
