// Limit-equilibrium factors of safety of the slope verification, derived in
// limit_equilibrium.cpp from the free bodies of Hoek & Bray (1981, Rock Slope Engineering,
// 3rd ed., chapters 7 and 9) and Wyllie & Mah (2004, 4th ed., chapters 6, 7 and 10). Units: kN
// per metre, kPa, m, degrees. Every factor here is a strength-reduction factor: the one F that,
// dividing tan(phi) and c of every surface that resists, brings the mechanism to limiting
// equilibrium (for a single plane this is the classical resisting / driving ratio).
#pragma once

#include <string>
#include <vector>

namespace dda::slope {

// A block of weight W on one plane dipping `dip`, with cohesion c over the contact length A, a
// water uplift U normal to the plane and a water force V on its back, horizontal, towards the
// face (the tension crack's).
struct PlaneBlock {
  double weight = 0.0;         // W, kN/m
  double dip = 0.0;            // psi_p, degrees
  double friction_angle = 0.0; // phi, degrees
  double cohesion = 0.0;       // c, kPa
  double length = 0.0;         // A, m: the plane's length under the block
  double uplift = 0.0;         // U, kN/m, normal to the plane
  double crack_push = 0.0;     // V, kN/m, horizontal, towards the face
  // A bolt's tension T (kN/m) as its two components: T_n pressing the block onto the plane,
  // T_s up the plane (Hoek & Bray's T sin and T cos of the bolt's angle, written by the
  // bolt's direction so that no convention for the angle is needed).
  double bolt_normal = 0.0;
  double bolt_along = 0.0;
};
// (c A + (W cos psi - U - V sin psi + T_n) tan phi) / (W sin psi + V cos psi - T_s).
double plane_factor(const PlaneBlock& b);
// The force (kN/m) along the plane that the block lacks at reduced strengths F (driving minus
// reduced resistance; > 0 beyond the factor of safety).
double plane_out_of_balance(const PlaneBlock& b, double factor);

// Hoek and Bray's plane failure with a vertical tension crack in the horizontal upper slope
// surface behind the crest, water standing zw deep in the crack and draining along the plane to
// the toe (pressure linear from gamma_w zw at the crack's bottom to 0 at the toe).
struct TensionCrackSlope {
  double height = 0.0;        // H, m
  double face_dip = 0.0;      // psi_f, degrees
  double plane_dip = 0.0;     // psi_p, degrees
  double crack_depth = 0.0;   // z, m
  double water_depth = 0.0;   // zw, m (0: dry)
  double unit_weight = 0.0;   // gamma, kN/m^3
  double water_unit_weight = 9.81;  // gamma_w, kN/m^3
  double friction_angle = 0.0;
  double cohesion = 0.0;
};
// The block as a PlaneBlock: A = (H - z) / sin psi_p, W from the section's area,
// U = gamma_w zw A / 2, V = gamma_w zw^2 / 2.
PlaneBlock tension_crack_block(const TensionCrackSlope& s);

// The active-passive (bi-planar) wedge: an upper (active) wedge on a steep plane pushes a lower
// (passive) wedge along a flatter one across a vertical interface. Wyllie & Mah (2004, ch. 7)
// and the two-block analysis of Hoek & Bray (1981).
struct BiplanarWedge {
  double upper_weight = 0.0, lower_weight = 0.0;  // kN/m
  double upper_dip = 0.0, lower_dip = 0.0;        // degrees
  double friction_angle = 0.0;                    // both planes, degrees
  double interface_friction = 0.0;                // the vertical interface, degrees
};
// The force (kN/m) along the lower plane that the lower wedge lacks at reduced strengths F
// (> 0: it must be held; 0 at the factor of safety).
double wedge_out_of_balance(const BiplanarWedge& w, double factor);
// The F at which wedge_out_of_balance is zero (bisection; it decreases with F).
double wedge_factor(const BiplanarWedge& w);

// Goodman and Bray's (1976) block toppling on a stepped base, as tabulated by Hoek & Bray
// (1981, ch. 9) and Wyllie & Mah (2004, ch. 10): columns of width dx numbered from the toe,
// their bases on steps dipping psi_p, heights y_n from a1, a2, b.
struct ToppleSlope {
  int columns = 16;
  int crest_column = 10;   // the column under the crest
  double width = 10.0;     // dx, m
  double base_dip = 30.0;  // psi_p, degrees
  double a1 = 5.0;         // dx tan(psi_f - psi_p): the face rises a1 per column
  double a2 = 5.0;         // dx tan(psi_p - psi_s): the upper slope falls a2 per column
  double b = 1.0;          // dx tan(psi_b - psi_p): the steps rise b per column
  double unit_weight = 25.0;  // kN/m^3
};
// Column heights y_1..y_n (m).
std::vector<double> column_heights(const ToppleSlope& s);

enum class ColumnMode { Stable, Topple, Slide };
std::string mode_name(ColumnMode m);

struct ToppleSolution {
  double toe_force = 0.0;  // P_0, kN/m: the force the toe column needs (> 0: unstable)
  std::vector<ColumnMode> modes;  // per column, from the toe
  std::vector<double> forces;     // P_n on the upper side of each column, kN/m
};
// The tabular method from the top column down at friction angle phi (degrees) on every
// surface (bases and column sides). `interface_shares` (optional): element n - 1 is the
// share of the limiting friction on the interface between columns n and n + 1 (1, Goodman
// and Bray's assumption, where it is not given).
ToppleSolution topple_at(const ToppleSlope& s, double friction_angle,
                         const std::vector<double>& interface_shares = {});
// The friction angle at which P_0 = 0 (bisection), degrees.
double limiting_friction_angle(const ToppleSlope& s,
                               const std::vector<double>& interface_shares = {});
// The strength-reduction factor at friction angle phi: tan(phi) / tan(phi_limit).
double topple_factor(const ToppleSlope& s, double friction_angle,
                     const std::vector<double>& interface_shares = {});

// The F at which `out_of_balance(F)` (increasing in F through 0 at the factor of safety)
// reaches `force`: the verdict's resolution (README "Tolerances"). Bisection on [lo, hi].
template <class Fn>
double factor_at_out_of_balance(Fn out_of_balance, double force, double lo, double hi) {
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    if (out_of_balance(mid) < force) {
      lo = mid;
    } else {
      hi = mid;
    }
  }
  return 0.5 * (lo + hi);
}

}  // namespace dda::slope
