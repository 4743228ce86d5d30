// CVODE reference solution of the rigid pendulum (see pendulum_reference.hpp).
#include "pendulum_reference.hpp"

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <numbers>
#include <stdexcept>
#include <string>

namespace dda {

namespace {

// Everything the C callbacks need, owned by the integrator (stable address).
struct CallbackData {
  double omega0_sq = 1.0;
  double theta0 = 0.0;
  std::string last_error;  // the last error message CVODE reported through its handler
};

// y = (theta, omega): theta' = omega, omega' = -omega0^2 sin(theta).
int pendulum_rhs(sunrealtype /*t*/, N_Vector y, N_Vector ydot, void* user) {
  const auto* d = static_cast<const CallbackData*>(user);
  NV_Ith_S(ydot, 0) = NV_Ith_S(y, 1);
  NV_Ith_S(ydot, 1) = -d->omega0_sq * std::sin(NV_Ith_S(y, 0));
  return 0;
}

int pendulum_jac(sunrealtype /*t*/, N_Vector y, N_Vector /*fy*/, SUNMatrix jac, void* user,
                 N_Vector /*tmp1*/, N_Vector /*tmp2*/, N_Vector /*tmp3*/) {
  const auto* d = static_cast<const CallbackData*>(user);
  SM_ELEMENT_D(jac, 0, 0) = 0.0;
  SM_ELEMENT_D(jac, 0, 1) = 1.0;
  SM_ELEMENT_D(jac, 1, 0) = -d->omega0_sq * std::cos(NV_Ith_S(y, 0));
  SM_ELEMENT_D(jac, 1, 1) = 0.0;
  return 0;
}

// Turning points: omega = 0.
int root_omega(sunrealtype /*t*/, N_Vector y, sunrealtype* g, void* /*user*/) {
  g[0] = NV_Ith_S(y, 1);
  return 0;
}

// Whole revolutions: theta - theta0 = 2 pi k  <=>  sin((theta - theta0) / 2) = 0.
int root_revolution(sunrealtype /*t*/, N_Vector y, sunrealtype* g, void* user) {
  const auto* d = static_cast<const CallbackData*>(user);
  g[0] = std::sin(0.5 * (NV_Ith_S(y, 0) - d->theta0));
  return 0;
}

void error_handler(int error_code, const char* module, const char* function, char* msg,
                   void* user) {
  if (error_code < 0) {  // errors only; warnings (CV_WARNING) are dropped
    auto* d = static_cast<CallbackData*>(user);
    d->last_error = std::string(module ? module : "") + "::" + (function ? function : "") + ": " +
                    (msg ? msg : "");
  }
}

enum class RootKind { none, omega, revolution };

// Energy per unit I_p above the resting state: e = omega^2 / 2 + omega0^2 (1 - cos theta).
double energy_above_rest(const PendulumParams& p) {
  return 0.5 * p.omega_init * p.omega_init + p.omega0_sq * (1.0 - std::cos(p.theta0));
}

void validate(const PendulumParams& p, const PendulumSolverOptions& opt) {
  if (!(std::isfinite(p.omega0_sq) && p.omega0_sq > 0.0)) {
    throw std::invalid_argument("pendulum: omega0_sq must be finite and > 0, got " +
                                std::to_string(p.omega0_sq));
  }
  if (!std::isfinite(p.theta0) || !std::isfinite(p.omega_init)) {
    throw std::invalid_argument("pendulum: theta0 and omega_init must be finite");
  }
  if (!(opt.rtol >= 1e-15 && opt.rtol <= 1e-3)) {
    throw std::invalid_argument("pendulum: rtol must lie in [1e-15, 1e-3], got " +
                                std::to_string(opt.rtol));
  }
  if (opt.max_steps <= 0) {
    throw std::invalid_argument("pendulum: max_steps must be > 0");
  }
}

// One CVODE integration of the pendulum from t = 0, optionally with one root function.
class PendulumIntegrator {
 public:
  PendulumIntegrator(const PendulumParams& p, const PendulumSolverOptions& opt, RootKind roots,
                     int root_direction) {
    data_.omega0_sq = p.omega0_sq;
    data_.theta0 = p.theta0;

    // Absolute tolerances scaled to the motion: rtol times the swing amplitude (theta) and
    // times the largest angular speed (omega), so that small swings are resolved as finely as
    // large ones. e <= 2 omega0^2 swings about the bottom with amplitude acos(1 - e/omega0^2);
    // above it the pendulum goes over the top and theta grows without bound.
    const double e = energy_above_rest(p);
    double theta_scale = std::abs(p.theta0);
    if (e < 2.0 * p.omega0_sq) {
      theta_scale = std::max(theta_scale, std::acos(std::clamp(1.0 - e / p.omega0_sq, -1.0, 1.0)));
    } else {
      theta_scale = std::max(theta_scale, std::numbers::pi);
    }
    double omega_scale = std::sqrt(2.0 * e);
    if (theta_scale == 0.0 || omega_scale == 0.0) {  // at rest at an equilibrium
      theta_scale = 1.0;
      omega_scale = std::sqrt(p.omega0_sq);
    }

    check(SUNContext_Create(nullptr, &r_.ctx), "SUNContext_Create");
    r_.y = N_VNew_Serial(2, r_.ctx);
    r_.abstol = N_VNew_Serial(2, r_.ctx);
    if (!r_.y || !r_.abstol) fail("N_VNew_Serial returned NULL");
    NV_Ith_S(r_.y, 0) = p.theta0;
    NV_Ith_S(r_.y, 1) = p.omega_init;
    NV_Ith_S(r_.abstol, 0) = opt.rtol * theta_scale;
    NV_Ith_S(r_.abstol, 1) = opt.rtol * omega_scale;

    // Adams: the problem is not stiff, and orders up to 12 take far fewer steps than BDF's 5
    // at rtol 1e-12.
    r_.mem = CVodeCreate(CV_ADAMS, r_.ctx);
    if (!r_.mem) fail("CVodeCreate returned NULL");
    check(CVodeSetErrHandlerFn(r_.mem, error_handler, &data_), "CVodeSetErrHandlerFn");
    check(CVodeInit(r_.mem, pendulum_rhs, 0.0, r_.y), "CVodeInit");
    check(CVodeSetUserData(r_.mem, &data_), "CVodeSetUserData");
    check(CVodeSVtolerances(r_.mem, opt.rtol, r_.abstol), "CVodeSVtolerances");
    check(CVodeSetMaxNumSteps(r_.mem, opt.max_steps), "CVodeSetMaxNumSteps");

    r_.matrix = SUNDenseMatrix(2, 2, r_.ctx);
    if (!r_.matrix) fail("SUNDenseMatrix returned NULL");
    r_.solver = SUNLinSol_Dense(r_.y, r_.matrix, r_.ctx);
    if (!r_.solver) fail("SUNLinSol_Dense returned NULL");
    check_ls(CVodeSetLinearSolver(r_.mem, r_.solver, r_.matrix), "CVodeSetLinearSolver");
    check_ls(CVodeSetJacFn(r_.mem, pendulum_jac), "CVodeSetJacFn");

    if (roots != RootKind::none) {
      check(CVodeRootInit(r_.mem, 1, roots == RootKind::omega ? root_omega : root_revolution),
            "CVodeRootInit");
      int dir = root_direction;
      check(CVodeSetRootDirection(r_.mem, &dir), "CVodeSetRootDirection");
      // omega stays identically zero only at rest at an equilibrium; no warning wanted then.
      check(CVodeSetNoInactiveRootWarn(r_.mem), "CVodeSetNoInactiveRootWarn");
    }
  }

  PendulumIntegrator(const PendulumIntegrator&) = delete;
  PendulumIntegrator& operator=(const PendulumIntegrator&) = delete;

  // Integrates towards tout (> the current time) and stops there or at the next root, whichever
  // comes first; returns true at a root. time(), theta() and omega() give the state reached.
  bool advance(double tout) {
    const int flag = CVode(r_.mem, tout, r_.y, &t_, CV_NORMAL);
    check(flag, "CVode");
    return flag == CV_ROOT_RETURN;
  }

  double time() const { return t_; }
  double theta() const { return NV_Ith_S(r_.y, 0); }
  double omega() const { return NV_Ith_S(r_.y, 1); }

 private:
  // Owns the SUNDIALS objects; a member, so it is destroyed even when the constructor throws.
  struct Resources {
    SUNContext ctx = nullptr;
    N_Vector y = nullptr;
    N_Vector abstol = nullptr;
    SUNMatrix matrix = nullptr;
    SUNLinearSolver solver = nullptr;
    void* mem = nullptr;
    Resources() = default;
    Resources(const Resources&) = delete;
    Resources& operator=(const Resources&) = delete;
    ~Resources() {
      if (mem) CVodeFree(&mem);
      if (solver) SUNLinSolFree(solver);
      if (matrix) SUNMatDestroy(matrix);
      if (abstol) N_VDestroy(abstol);
      if (y) N_VDestroy(y);
      if (ctx) SUNContext_Free(&ctx);
    }
  };

  [[noreturn]] void fail(const std::string& what) const {
    throw std::runtime_error("pendulum reference (CVODE): " + what);
  }

  std::string details() const { return data_.last_error.empty() ? "" : " - " + data_.last_error; }

  void check(int flag, const char* call) const {
    if (flag >= 0) return;
    char* name = CVodeGetReturnFlagName(flag);
    const std::string flag_name = name ? name : "unknown flag";
    std::free(name);
    fail(std::string(call) + " failed with " + flag_name + " (" + std::to_string(flag) + ")" +
         details());
  }

  void check_ls(int flag, const char* call) const {
    if (flag >= 0) return;
    char* name = CVodeGetLinReturnFlagName(flag);
    const std::string flag_name = name ? name : "unknown flag";
    std::free(name);
    fail(std::string(call) + " failed with " + flag_name + " (" + std::to_string(flag) + ")" +
         details());
  }

  CallbackData data_;
  Resources r_;
  double t_ = 0.0;
};

void validate_duration(double duration) {
  if (!(std::isfinite(duration) && duration >= 0.0)) {
    throw std::invalid_argument("pendulum: duration must be finite and >= 0, got " +
                                std::to_string(duration));
  }
}

}  // namespace

PendulumParams pendulum_params(double mass, double gravity, double arm, double pivot_inertia,
                               double theta0, double omega_init) {
  if (!(mass > 0.0 && gravity > 0.0 && arm > 0.0 && pivot_inertia > 0.0) ||
      !std::isfinite(mass * gravity * arm / pivot_inertia)) {
    throw std::invalid_argument("pendulum_params: mass, gravity, arm and pivot_inertia must be "
                                "finite and > 0");
  }
  if (pivot_inertia < mass * arm * arm * (1.0 - 1e-12)) {
    throw std::invalid_argument("pendulum_params: pivot_inertia must be at least mass * arm^2 "
                                "(parallel axis theorem)");
  }
  return PendulumParams{mass * gravity * arm / pivot_inertia, theta0, omega_init};
}

double ngon_centroidal_inertia_per_mass(int n, double circumradius) {
  if (n < 3) throw std::invalid_argument("ngon_centroidal_inertia_per_mass: n must be >= 3");
  if (!(std::isfinite(circumradius) && circumradius > 0.0)) {
    throw std::invalid_argument("ngon_centroidal_inertia_per_mass: circumradius must be > 0");
  }
  const double c = std::cos(std::numbers::pi / n);
  return circumradius * circumradius / 6.0 * (1.0 + 2.0 * c * c);
}

PendulumSamples pendulum_sample(const PendulumParams& p, const std::vector<double>& times,
                                const PendulumSolverOptions& opt) {
  validate(p, opt);
  for (std::size_t i = 0; i < times.size(); ++i) {
    if (!(std::isfinite(times[i]) && times[i] >= 0.0) || (i > 0 && times[i] < times[i - 1])) {
      throw std::invalid_argument("pendulum_sample: times must be finite, >= 0 and "
                                  "non-decreasing (times[" + std::to_string(i) + "])");
    }
  }
  PendulumSamples out;
  out.time = times;
  out.theta.reserve(times.size());
  out.omega.reserve(times.size());
  PendulumIntegrator integ(p, opt, RootKind::none, 0);
  for (std::size_t i = 0; i < times.size(); ++i) {
    const double t = times[i];
    if (t == 0.0) {
      out.theta.push_back(p.theta0);
      out.omega.push_back(p.omega_init);
    } else if (i > 0 && t == times[i - 1]) {
      out.theta.push_back(out.theta.back());
      out.omega.push_back(out.omega.back());
    } else {
      integ.advance(t);
      out.theta.push_back(integ.theta());
      out.omega.push_back(integ.omega());
    }
  }
  return out;
}

double pendulum_period(const PendulumParams& p, const PendulumSolverOptions& opt) {
  validate(p, opt);
  const double e = energy_above_rest(p);
  const double two_w2 = 2.0 * p.omega0_sq;
  if (e == 0.0 || e == two_w2) {
    throw std::invalid_argument(
        e == 0.0 ? "pendulum_period: at rest at the bottom, there is no motion"
                 : "pendulum_period: on the separatrix (energy of the inverted rest position), "
                   "the period is infinite");
  }
  const double limit = 1e4 * 2.0 * std::numbers::pi / std::sqrt(p.omega0_sq);
  if (e < two_w2) {
    // Swinging about the bottom: successive upward zero crossings of omega.
    PendulumIntegrator integ(p, opt, RootKind::omega, +1);
    std::vector<double> crossings;
    while (crossings.size() < 2) {
      if (!integ.advance(limit)) break;
      crossings.push_back(integ.time());
    }
    if (crossings.size() == 2) return crossings[1] - crossings[0];
  } else {
    // Over the top: the first return of theta to theta0 + 2 pi k (k = +-1).
    PendulumIntegrator integ(p, opt, RootKind::revolution, 0);
    if (integ.advance(limit)) return integ.time();
  }
  throw std::runtime_error("pendulum_period: no full period within 1e4 small-amplitude periods");
}

std::vector<PendulumTurningPoint> pendulum_turning_points(const PendulumParams& p, double duration,
                                                          const PendulumSolverOptions& opt) {
  validate(p, opt);
  validate_duration(duration);
  std::vector<PendulumTurningPoint> out;
  if (duration == 0.0) return out;
  PendulumIntegrator integ(p, opt, RootKind::omega, 0);
  while (integ.advance(duration)) {
    out.push_back({integ.time(), integ.theta()});
  }
  return out;
}

double pendulum_amplitude(const PendulumParams& p, double duration,
                          const PendulumSolverOptions& opt) {
  validate(p, opt);
  validate_duration(duration);
  double amplitude = std::abs(p.theta0);
  if (duration == 0.0) return amplitude;
  PendulumIntegrator integ(p, opt, RootKind::omega, 0);
  while (integ.advance(duration)) {
    amplitude = std::max(amplitude, std::abs(integ.theta()));
  }
  return std::max(amplitude, std::abs(integ.theta()));  // the state at t = duration
}

}  // namespace dda
