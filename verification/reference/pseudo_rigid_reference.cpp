// CVODE reference of one pseudo-rigid body (see pseudo_rigid_reference.hpp).
#include "pseudo_rigid_reference.hpp"

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <Eigen/Eigenvalues>

#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

namespace dda::reference {
namespace {

Mat2 rotation(double theta) {
  Mat2 r;
  r << std::cos(theta), -std::sin(theta), std::sin(theta), std::cos(theta);
  return r;
}

Mat2 quarter() {
  Mat2 j;
  j << 0.0, -1.0, 1.0, 0.0;
  return j;
}

// d(strain tensor)/d(e_k) for (e_x, e_y, g_xy): engineering shear puts 1/2 off the diagonal.
std::array<Mat2, 3> strain_directions() {
  Mat2 a, b, c;
  a << 1.0, 0.0, 0.0, 0.0;
  b << 0.0, 0.0, 0.0, 1.0;
  c << 0.0, 0.5, 0.5, 0.0;
  return {a, b, c};
}

Mat2 stretch(const Vec3& e) {
  Mat2 u;
  u << 1.0 + e[0], 0.5 * e[2], 0.5 * e[2], 1.0 + e[1];
  return u;
}

// U's principal stretches and axes (columns).
struct Principal {
  Vec2 stretch;
  Mat2 axes;
};

Principal principal(const Vec3& e) {
  const Eigen::SelfAdjointEigenSolver<Mat2> eig(stretch(e));
  if (eig.info() != Eigen::Success || !(eig.eigenvalues().minCoeff() > 0.0)) {
    throw std::invalid_argument("pseudo-rigid reference: the stretch U is not positive definite");
  }
  return {eig.eigenvalues(), eig.eigenvectors()};
}

Vec3 voigt(const Mat2& t) { return Vec3(t(0, 0), t(1, 1), 2.0 * t(0, 1)); }

// (ln l1 - ln l2) / (l1 - l2), the off-diagonal factor of the logarithm's derivative, without
// the cancellation of the difference of logarithms when l1 is near l2 (the limit 1/l).
double log_divided_difference(double l1, double l2) {
  const double d = l1 - l2;
  return d == 0.0 ? 1.0 / l2 : std::log1p(d / l2) / d;
}

// dF/dq for q = (theta, e_x, e_y, g_xy), up to the common factor R(theta) on the left, which
// leaves every tr(A J0 B^T) unchanged: JU and the three strain directions.
std::array<Mat2, 4> shape_derivatives(const Vec3& e) {
  const std::array<Mat2, 3> s = strain_directions();
  return {quarter() * stretch(e), s[0], s[1], s[2]};
}

// The generalised force of the potential energy, -dV/dq.
Vec6 potential_force(const PseudoRigidBody& b, const Vec6& q) {
  Vec6 f = Vec6::Zero();
  f.head<2>() = b.mass * b.gravity;
  f.tail<3>() = pseudo_rigid_elastic_force(b, q.tail<3>());
  if (b.pinned) {
    const Mat2 r = rotation(q[2]);
    const Vec3 e = q.tail<3>();
    const Vec2 at = q.head<2>() + r * stretch(e) * b.pin_offset;
    const Vec2 pull = b.pin_stiffness * (b.anchor - at);
    const std::array<Mat2, 4> a = shape_derivatives(e);
    f.head<2>() += pull;
    for (int k = 0; k < 4; ++k) f[2 + k] += pull.dot(r * a[static_cast<std::size_t>(k)] * b.pin_offset);
  }
  return f;
}

struct Data {
  PseudoRigidBody body;
  std::string last_error;
};

// y = (q, q'): q'' = M^-1 (-dV/dq - (M' q' - 1/2 d(q'^T M q')/dq)).
int rhs(sunrealtype /*t*/, N_Vector y, N_Vector ydot, void* user) {
  const auto* d = static_cast<const Data*>(user);
  Vec6 q, v;
  for (int i = 0; i < 6; ++i) {
    q[i] = NV_Ith_S(y, i);
    v[i] = NV_Ith_S(y, 6 + i);
  }
  const Vec3 e = q.tail<3>();
  // M depends on the strain only, quadratically: central differences are exact to round-off.
  constexpr double h = 1e-3;
  std::array<Mat6, 3> dm;
  for (int j = 0; j < 3; ++j) {
    Vec3 up = e, down = e;
    up[j] += h;
    down[j] -= h;
    dm[static_cast<std::size_t>(j)] =
        (pseudo_rigid_mass(d->body, up) - pseudo_rigid_mass(d->body, down)) / (2.0 * h);
  }
  Mat6 m_dot = Mat6::Zero();
  Vec6 half_gradient = Vec6::Zero();
  for (int j = 0; j < 3; ++j) {
    m_dot += dm[static_cast<std::size_t>(j)] * v[3 + j];
    half_gradient[3 + j] = 0.5 * v.dot(dm[static_cast<std::size_t>(j)] * v);
  }
  const Vec6 force = potential_force(d->body, q) - (m_dot * v - half_gradient);
  const Vec6 a = pseudo_rigid_mass(d->body, e).ldlt().solve(force);
  for (int i = 0; i < 6; ++i) {
    NV_Ith_S(ydot, i) = v[i];
    NV_Ith_S(ydot, 6 + i) = a[i];
  }
  return 0;
}

void error_handler(int code, const char* module, const char* function, char* msg, void* user) {
  if (code < 0) {
    static_cast<Data*>(user)->last_error = std::string(module ? module : "") + "::" +
                                           (function ? function : "") + ": " + (msg ? msg : "");
  }
}

// The CVODE objects of one integration, released in any case.
struct Resources {
  SUNContext ctx = nullptr;
  N_Vector y = nullptr, abstol = nullptr;
  SUNMatrix jac = nullptr;
  SUNLinearSolver solver = nullptr;
  void* cvode = nullptr;
  ~Resources() {
    if (cvode) CVodeFree(&cvode);
    if (solver) SUNLinSolFree(solver);
    if (jac) SUNMatDestroy(jac);
    if (abstol) N_VDestroy(abstol);
    if (y) N_VDestroy(y);
    if (ctx) SUNContext_Free(&ctx);
  }
};

void check(int flag, const char* call, const Data& d) {
  if (flag < 0) {
    throw std::runtime_error(std::string("pseudo-rigid reference: ") + call + " failed (flag " +
                             std::to_string(flag) + ")" +
                             (d.last_error.empty() ? "" : ": " + d.last_error));
  }
}

}  // namespace

Vec3 hencky_of_biot(const Vec3& biot) {
  const Principal p = principal(biot);
  const Vec2 logs(std::log(p.stretch[0]), std::log(p.stretch[1]));
  return voigt(p.axes * logs.asDiagonal() * p.axes.transpose());
}

double pseudo_rigid_elastic_energy(const PseudoRigidBody& body, const Vec3& strain) {
  const Vec3 h = body.law == ElasticLaw::Hencky ? hencky_of_biot(strain) : strain;
  return 0.5 * body.area * h.dot(body.elastic * h);
}

Vec3 pseudo_rigid_elastic_force(const PseudoRigidBody& body, const Vec3& strain) {
  if (body.law == ElasticLaw::Linear) return -body.area * (body.elastic * strain);
  // The Kirchhoff stress in the body's axes from the Hencky strain, then the Biot stress
  // T_B = L(tau^) in U's principal axes (header), then -A0 T_B : dU/de_k.
  const Principal p = principal(strain);
  const Vec3 t = body.elastic * hencky_of_biot(strain);
  Mat2 tau;
  tau << t[0], t[2], t[2], t[1];
  Mat2 biot = p.axes.transpose() * tau * p.axes;
  biot(0, 0) /= p.stretch[0];
  biot(1, 1) /= p.stretch[1];
  const double off = log_divided_difference(p.stretch[0], p.stretch[1]);
  biot(0, 1) *= off;
  biot(1, 0) *= off;
  biot = p.axes * biot * p.axes.transpose();
  // dU/de: 1 on the diagonal entries for e_x and e_y, 1/2 on both off-diagonal ones for g_xy.
  return -body.area * Vec3(biot(0, 0), biot(1, 1), 0.5 * (biot(0, 1) + biot(1, 0)));
}

Mat6 pseudo_rigid_mass(const PseudoRigidBody& body, const Vec3& strain) {
  Mat6 m = Mat6::Zero();
  m(0, 0) = m(1, 1) = body.mass;
  const std::array<Mat2, 4> a = shape_derivatives(strain);
  for (int k = 0; k < 4; ++k) {
    for (int l = 0; l < 4; ++l) {
      m(2 + k, 2 + l) = (a[static_cast<std::size_t>(k)] * body.inertia *
                         a[static_cast<std::size_t>(l)].transpose())
                            .trace();
    }
  }
  return m;
}

std::vector<PseudoRigidState> pseudo_rigid_sample(const PseudoRigidBody& body,
                                                  const PseudoRigidState& start,
                                                  const std::vector<double>& times,
                                                  const PseudoRigidOptions& opt) {
  if (!(body.mass > 0.0 && body.area > 0.0)) {
    throw std::invalid_argument("pseudo-rigid reference: mass and area must be > 0");
  }
  for (std::size_t i = 0; i < times.size(); ++i) {
    if (times[i] < start.time || (i > 0 && times[i] < times[i - 1])) {
      throw std::invalid_argument("pseudo-rigid reference: times must be non-decreasing from the start");
    }
  }
  Data data{body, {}};
  Resources r;
  check(SUNContext_Create(nullptr, &r.ctx), "SUNContext_Create", data);
  r.y = N_VNew_Serial(12, r.ctx);
  r.abstol = N_VNew_Serial(12, r.ctx);
  const Vec6 q0 = (Vec6() << start.centroid, start.angle, start.strain).finished();
  const Vec6 v0 = (Vec6() << start.velocity, start.omega, start.strain_rate).finished();
  const double scales[6] = {opt.length_scale, opt.length_scale, 1.0,
                            opt.strain_scale, opt.strain_scale, opt.strain_scale};
  for (int i = 0; i < 6; ++i) {
    NV_Ith_S(r.y, i) = q0[i];
    NV_Ith_S(r.y, 6 + i) = v0[i];
    NV_Ith_S(r.abstol, i) = opt.rtol * scales[i];
    NV_Ith_S(r.abstol, 6 + i) = opt.rtol * scales[i];  // per second: rates of order 1/s
  }
  r.cvode = CVodeCreate(CV_BDF, r.ctx);
  if (!r.cvode) throw std::runtime_error("pseudo-rigid reference: CVodeCreate returned NULL");
  check(CVodeSetErrHandlerFn(r.cvode, error_handler, &data), "CVodeSetErrHandlerFn", data);
  check(CVodeInit(r.cvode, rhs, start.time, r.y), "CVodeInit", data);
  check(CVodeSVtolerances(r.cvode, opt.rtol, r.abstol), "CVodeSVtolerances", data);
  check(CVodeSetUserData(r.cvode, &data), "CVodeSetUserData", data);
  check(CVodeSetMaxNumSteps(r.cvode, opt.max_steps), "CVodeSetMaxNumSteps", data);
  r.jac = SUNDenseMatrix(12, 12, r.ctx);
  r.solver = SUNLinSol_Dense(r.y, r.jac, r.ctx);
  check(CVodeSetLinearSolver(r.cvode, r.solver, r.jac), "CVodeSetLinearSolver", data);

  std::vector<PseudoRigidState> out;
  out.reserve(times.size());
  double t = start.time;
  for (double target : times) {
    if (target > t) check(CVode(r.cvode, target, r.y, &t, CV_NORMAL), "CVode", data);
    PseudoRigidState s;
    s.time = target;
    s.centroid = Vec2(NV_Ith_S(r.y, 0), NV_Ith_S(r.y, 1));
    s.angle = NV_Ith_S(r.y, 2);
    s.strain = Vec3(NV_Ith_S(r.y, 3), NV_Ith_S(r.y, 4), NV_Ith_S(r.y, 5));
    s.velocity = Vec2(NV_Ith_S(r.y, 6), NV_Ith_S(r.y, 7));
    s.omega = NV_Ith_S(r.y, 8);
    s.strain_rate = Vec3(NV_Ith_S(r.y, 9), NV_Ith_S(r.y, 10), NV_Ith_S(r.y, 11));
    out.push_back(s);
  }
  return out;
}

}  // namespace dda::reference
