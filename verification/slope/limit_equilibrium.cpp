#include "limit_equilibrium.hpp"

#include <cassert>
#include <cmath>

namespace dda::slope {
namespace {

constexpr double kPi = 3.14159265358979323846;
double rad(double deg) { return deg * kPi / 180.0; }

}  // namespace

// One plane (Hoek & Bray 1981, ch. 7; Wyllie & Mah 2004, ch. 6). Resolve the block's loads
// normal and parallel to the plane. Normal: the plane pushes back N = W cos psi - U - V sin psi
// (the uplift and the crack water's normal component take load off the plane). Parallel, down
// the dip: W sin psi + V cos psi drives. The plane resists with at most c A + N tan phi. With
// c and tan phi divided by F, limiting equilibrium c A / F + N tan phi / F = driving gives
// F = (c A + N tan phi) / driving: on one plane the strength-reduction factor is the classical
// resisting / driving ratio.
double plane_factor(const PlaneBlock& b) {
  const double psi = rad(b.dip);
  const double normal =
      b.weight * std::cos(psi) - b.uplift - b.crack_push * std::sin(psi) + b.bolt_normal;
  const double driving = b.weight * std::sin(psi) + b.crack_push * std::cos(psi) - b.bolt_along;
  return (b.cohesion * b.length + normal * std::tan(rad(b.friction_angle))) / driving;
}

double plane_out_of_balance(const PlaneBlock& b, double factor) {
  const double psi = rad(b.dip);
  const double normal =
      b.weight * std::cos(psi) - b.uplift - b.crack_push * std::sin(psi) + b.bolt_normal;
  const double driving = b.weight * std::sin(psi) + b.crack_push * std::cos(psi) - b.bolt_along;
  return driving - (b.cohesion * b.length + normal * std::tan(rad(b.friction_angle))) / factor;
}

// The tension-crack block (Hoek & Bray 1981, ch. 7, crack in the upper slope surface).
// Its section is the toe (0, 0), the crest (H cot psi_f, H), the crack's top and bottom on the
// vertical x = (H - z) cot psi_p: the plane from the toe to the crack's bottom is
// A = (H - z) / sin psi_p long, and the area, the trapezoid under the top surface between the
// face and the crack less the triangle under the plane, is
// H^2 / 2 [(1 - (z/H)^2) cot psi_p - cot psi_f]. Water zw deep in the crack: hydrostatic in the
// crack, V = gamma_w zw^2 / 2 on the block's back, horizontal; along the plane the pressure
// falls linearly from gamma_w zw at the crack's bottom to 0 at the toe, U = gamma_w zw A / 2.
PlaneBlock tension_crack_block(const TensionCrackSlope& s) {
  const double zr = s.crack_depth / s.height;
  PlaneBlock b;
  b.dip = s.plane_dip;
  b.friction_angle = s.friction_angle;
  b.cohesion = s.cohesion;
  b.length = (s.height - s.crack_depth) / std::sin(rad(s.plane_dip));
  b.weight = 0.5 * s.unit_weight * s.height * s.height *
             ((1.0 - zr * zr) / std::tan(rad(s.plane_dip)) - 1.0 / std::tan(rad(s.face_dip)));
  b.uplift = 0.5 * s.water_unit_weight * s.water_depth * b.length;
  b.crack_push = 0.5 * s.water_unit_weight * s.water_depth * s.water_depth;
  return b;
}

// The two wedges (Wyllie & Mah 2004, ch. 7; the two-block analysis of Hoek & Bray 1981). Take x towards the
// slope (the upper wedge is on the +x side of the interface) and both wedges sliding down-dip,
// towards -x. The upper wedge moves down relative to the lower one, so across the vertical
// interface the lower wedge pushes it with P (+x, normal) and holds it up with P tan(delta_m)
// (+y). On its plane (up-dip unit t1 = (cos a1, sin a1), normal n1 = (-sin a1, cos a1)) the
// upper wedge gets N1 n1 and N1 tan(phi_m) t1. Its equilibrium along n1 and t1:
//   N1 = W1 cos a1 + P (sin a1 - tan d_m cos a1),
//   W1 sin a1 = N1 tan phi_m + P (cos a1 + tan d_m sin a1),
// so P = W1 (sin a1 - tan phi_m cos a1) / (cos a1 + tan d_m sin a1 + tan phi_m (sin a1 - tan d_m cos a1)).
// The lower wedge takes -P and -P tan d_m from the upper one; along its plane (a2):
//   N2 = W2 cos a2 - P (sin a2 - tan d_m cos a2),
//   S2 = W2 sin a2 + P (cos a2 + tan d_m sin a2)   (the shear it needs from its plane).
// Out of balance: S2 - N2 tan phi_m; zero at the factor of safety. The reduced strengths are
// tan phi_m = tan phi / F and tan d_m = tan delta / F on every surface.
double wedge_out_of_balance(const BiplanarWedge& w, double factor) {
  const double tp = std::tan(rad(w.friction_angle)) / factor;
  const double td = std::tan(rad(w.interface_friction)) / factor;
  const double a1 = rad(w.upper_dip), a2 = rad(w.lower_dip);
  const double push = w.upper_weight * (std::sin(a1) - tp * std::cos(a1)) /
                      (std::cos(a1) + td * std::sin(a1) + tp * (std::sin(a1) - td * std::cos(a1)));
  const double normal2 = w.lower_weight * std::cos(a2) - push * (std::sin(a2) - td * std::cos(a2));
  const double shear2 = w.lower_weight * std::sin(a2) + push * (std::cos(a2) + td * std::sin(a2));
  return shear2 - normal2 * tp;
}

double wedge_factor(const BiplanarWedge& w) {
  return factor_at_out_of_balance([&](double f) { return wedge_out_of_balance(w, f); }, 0.0, 0.05, 20.0);
}

// Heights (Wyllie & Mah 2004, ch. 10): below the crest the face climbs a1 and the step b per
// column, so y_n = n (a1 - b); above it the upper slope falls a2 while the step still climbs b,
// so y_n = y_(n-1) - a2 - b.
std::vector<double> column_heights(const ToppleSlope& s) {
  std::vector<double> y;
  for (int n = 1; n <= s.columns; ++n) {
    y.push_back(n <= s.crest_column ? n * (s.a1 - s.b) : y.back() - s.a2 - s.b);
  }
  return y;
}

std::string mode_name(ColumnMode m) {
  switch (m) {
    case ColumnMode::Stable: return "stable";
    case ColumnMode::Topple: return "topple";
    case ColumnMode::Slide: return "slide";
  }
  return "?";
}

// The tabular method (Goodman & Bray 1976; Hoek & Bray 1981, ch. 9). In the frame of the steps
// (x down the base dip psi, y up the columns' sides), column n of height y and weight
// W = gamma y dx takes P_n from the column above at height M_n on its upper side and P_(n-1)
// from the column below at height L_n on its lower side, each with friction P tan phi along
// the side. Where the columns meet: below the crest the upper neighbour is taller, so it
// touches column n at n's top corner (M_n = y_n) and column n rests on the lower neighbour's
// top, a1 lower (L_n = y_n - a1); above the crest M_n = y_n - a2 and L_n = y_n; the crest
// column has M_n = y_n - a2, L_n = y_n - a1.
//  - Toppling about its toe corner: moments about that corner give
//    P_(n-1),t = [P_n (M_n - dx tan phi) + W/2 (y sin psi - dx cos psi)] / L_n
//    (the upper side's friction acts dx from the corner; the lower side's passes through it).
//  - Sliding on its base: along and across the base, with the base's S = R tan phi and both
//    sides' frictions, P_(n-1),s = P_n - W (cos psi tan phi - sin psi) / (1 - tan^2 phi).
// Goodman and Bray put the limiting friction P tan phi on every side. With a share s <= 1 of
// it on an interface (`interface_shares`, README "Toppling: the interface that does not
// slip"), t_u = s_n tan phi on column n's upper side and t_l = s_(n-1) tan phi on its lower
// side: the same balances give
//    P_(n-1),t = [P_n (M_n - dx t_u) + W/2 (y sin psi - dx cos psi)] / L_n,
//    P_(n-1),s = [P_n (1 - tan phi t_u) + W (sin psi - cos psi tan phi)] / (1 - tan phi t_l),
// which are the two above when both shares are 1.
// From the top: columns that neither topple nor slide without load (both negative) pass
// P = 0 down; from the first that topples, each passes the larger of the two, until sliding
// needs more than toppling: from there down all slide. P_0 is what the toe would need.
ToppleSolution topple_at(const ToppleSlope& s, double friction_angle,
                         const std::vector<double>& interface_shares) {
  const std::vector<double> y = column_heights(s);
  const double t = std::tan(rad(friction_angle));
  // The share on the interface between columns n and n + 1 (1 where none is given).
  const auto share = [&](int n) {
    const auto i = static_cast<std::size_t>(n - 1);
    return n >= 1 && i < interface_shares.size() ? interface_shares[i] : 1.0;
  };
  const double sp = std::sin(rad(s.base_dip)), cp = std::cos(rad(s.base_dip));
  ToppleSolution out;
  out.modes.assign(y.size(), ColumnMode::Stable);
  out.forces.assign(y.size(), 0.0);
  ColumnMode regime = ColumnMode::Stable;
  double p = 0.0;  // P_n on the upper side of the column being solved
  for (int n = s.columns; n >= 1; --n) {
    const double h = y[static_cast<std::size_t>(n - 1)];
    const double w = s.unit_weight * h * s.width;
    const double m = n < s.crest_column ? h : h - s.a2;
    const double l = n > s.crest_column ? h : h - s.a1;
    const double t_upper = share(n) * t, t_lower = share(n - 1) * t;
    const double topple = (p * (m - s.width * t_upper) + 0.5 * w * (h * sp - s.width * cp)) / l;
    const double slide = (p * (1.0 - t * t_upper) + w * (sp - cp * t)) / (1.0 - t * t_lower);
    ColumnMode mode;
    double below;
    if (regime == ColumnMode::Stable && topple <= 0.0 && slide <= 0.0) {
      mode = ColumnMode::Stable;
      below = 0.0;
    } else if (regime != ColumnMode::Slide && topple > slide) {
      mode = ColumnMode::Topple;
      below = topple;
    } else {
      mode = ColumnMode::Slide;
      below = slide;
    }
    regime = mode;
    out.forces[static_cast<std::size_t>(n - 1)] = p;
    out.modes[static_cast<std::size_t>(n - 1)] = mode;
    p = below;
  }
  out.toe_force = p;
  return out;
}

double limiting_friction_angle(const ToppleSlope& s, const std::vector<double>& interface_shares) {
  // P_0 falls as phi rises; bisection between a friction too small to hold anything and one
  // that holds every column.
  double lo = 1.0, hi = 80.0;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    if (topple_at(s, mid, interface_shares).toe_force > 0.0) {
      lo = mid;
    } else {
      hi = mid;
    }
  }
  return 0.5 * (lo + hi);
}

double topple_factor(const ToppleSlope& s, double friction_angle,
                     const std::vector<double>& interface_shares) {
  return std::tan(rad(friction_angle)) / std::tan(rad(limiting_friction_angle(s, interface_shares)));
}

}  // namespace dda::slope
