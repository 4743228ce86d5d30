#include "slope_cases.hpp"

#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <numeric>

#include "cutting/model.hpp"
#include "io/cut_scene.hpp"
#include "io/model_reader.hpp"
#include "kinematics/polygon.hpp"

namespace dda::slope {
namespace {

using json = nlohmann::json;
constexpr double kPi = 3.14159265358979323846;
constexpr double kG = 9.81;              // m/s^2
constexpr double kWaterWeight = 9810.0;  // N/m^3 (gamma_w = 9.81 kN/m^3, as Hoek & Bray)
double rad(double deg) { return deg * kPi / 180.0; }

struct P {
  double x, y;
};
P along(double s, double dip) { return {s * std::cos(rad(dip)), s * std::sin(rad(dip))}; }
json pt(P p) { return json::array({p.x, p.y}); }
json polygon(const std::vector<P>& ps) {
  json out = json::array();
  for (const P& p : ps) out.push_back(pt(p));
  return out;
}
double area(const std::vector<P>& ps) {
  double a = 0.0;
  for (std::size_t i = 0; i < ps.size(); ++i) {
    const P& p = ps[i];
    const P& q = ps[(i + 1) % ps.size()];
    a += p.x * q.y - q.x * p.y;
  }
  return 0.5 * a;
}

json joint(double phi, double cohesion_pa, double tensile_pa) {
  return {{"friction_angle", phi}, {"cohesion", cohesion_pa}, {"tensile_strength", tensile_pa},
          {"law", "coulomb_slip"}};
}

// What every case shares: rigid free blocks (limit equilibrium's rigid bodies; the contact
// springs are the only compliance), gravity ramped up over a static stage, then the trials
// with the control's time step. max_displacement_ratio 0.001 of w0 keeps a step's motion at
// centimetres on these 50-200 m scenes.
json scene_base(double unit_weight_kn, double time_step, double consolidation) {
  return {
      {"gravity", {0.0, -kG}},
      {"control", {{"time_step", time_step}, {"max_displacement_ratio", 0.001}, {"output_every", 100}}},
      {"materials",
       {{"rock", {{"model", "elastic"}, {"density", unit_weight_kn * 1e3 / kG}, {"young", 1e10},
                  {"poisson", 0.25}, {"rigid", true}}}}},
      {"blocks", json::array()},
      {"stages", {{{"duration", consolidation}, {"dynamic_coefficient", 0.0}, {"gravity_ramp", {0.0, 1.0}}}}},
  };
}

void add_block(json& scene, const std::vector<P>& vertices, bool fixed) {
  json b = {{"vertices", polygon(vertices)}, {"material", "rock"}};
  if (fixed) b["fixed"] = true;
  scene["blocks"].push_back(b);
}

// The verdict's resolution: how far beyond `le` the out-of-balance force reaches
// 2 a_det x the moving weight (on one plane: F - FS = FS x 2 a_det / sin(dip) to first order,
// the rule of tests/studies/test_strength_reduction.cpp).
template <class Fn>
double resolution_of(Fn out_of_balance, double le, double moving_weight, double a_det) {
  return factor_at_out_of_balance(out_of_balance, 2.0 * a_det * moving_weight, le, 3.0 * le) - le;
}

// ---- case 1: one block on a plane at 30 degrees (Hoek & Bray 1981, ch. 7) ----
// W = 1000 kN/m, base 10 m on the plane, 2500 kg/m^3: the block is W / (rho g L) thick.
SlopeCase planar_case(const std::string& name, double cohesion_kpa, double uplift_kn,
                      double published, double a_det, double seismic = 0.0) {
  PlaneBlock pb = planar_block(cohesion_kpa, uplift_kn);
  // A seismic coefficient kh pushes the block horizontally out of the face with kh W: the
  // closed form's horizontal force V (its tension-crack water thrust).
  pb.crack_push = seismic * pb.weight;
  SlopeCase c;
  c.name = name;
  c.published = published;
  c.le_factor = plane_factor(pb);
  c.resolution = resolution_of([&](double f) { return plane_out_of_balance(pb, f); }, c.le_factor,
                               pb.weight, a_det);
  const double unit_weight = 2500.0 * kG / 1e3;
  const double thick = pb.weight / (unit_weight * pb.length);
  const double dip = pb.dip;
  auto at = [&](double s, double q) {
    const P t = along(s, dip), n = along(q, dip + 90.0);
    return P{t.x + n.x, t.y + n.y};
  };
  json scene = scene_base(unit_weight, 0.002, 0.5);
  scene["joint_materials"] = {{"default", joint(pb.friction_angle, cohesion_kpa * 1e3, 0.0)}};
  // The fixed plane runs well beyond the block both ways (no vertex of it under the block).
  add_block(scene, {at(-10, 0), at(-10, -3), at(30, -3), at(30, 0)}, true);
  add_block(scene, {at(5, 0), at(5 + pb.length, 0), at(5 + pb.length, thick), at(5, thick)}, false);
  c.title = "block on a 30 deg plane, phi 30, c " + std::to_string(static_cast<int>(cohesion_kpa)) + " kPa";
  if (uplift_kn > 0.0) {
    // Uniform uplift U over the base: a phreatic line parallel to the plane, hw = U / (gamma_w L)
    // above it (vertically; pressure is gamma_w (y_line - y)), so every point of the base is at
    // gamma_w hw = U / L. Only joints carry pressure: the block's free faces, under the line
    // too, carry none, as Hoek & Bray's U alone acts.
    const double hw = uplift_kn * 1e3 / (kWaterWeight * pb.length);
    const P a = at(-20, 0), b = at(40, 0);
    scene["water"] = {{"phreatic_line", {{a.x, a.y + hw}, {b.x, b.y + hw}}}, {"unit_weight", kWaterWeight}};
    c.needs_water = true;
    c.title += ", uplift U = " + std::to_string(static_cast<int>(uplift_kn)) + " kN/m";
  }
  if (seismic > 0.0) {
    // The plane rises towards +x, so the face, and the way out of the slope, is towards -x.
    c.seismic_coefficient = -seismic;
    c.title += ", seismic coefficient " + std::to_string(seismic).substr(0, 4) + " out of the slope";
  }
  c.scene = scene.dump();
  return c;
}

// ---- case 2: Hoek and Bray's tension-crack slope (1981, ch. 7 worked example) ----
SlopeCase hoek_bray_case(const std::string& name, double water_depth, double published,
                         double a_det) {
  const TensionCrackSlope s = hoek_bray_slope(water_depth);
  const PlaneBlock pb = tension_crack_block(s);
  SlopeCase c;
  c.name = name;
  c.published = published;
  c.le_factor = plane_factor(pb);
  c.resolution = resolution_of([&](double f) { return plane_out_of_balance(pb, f); }, c.le_factor,
                               pb.weight, a_det);
  const double h = s.height, zc = s.height - s.crack_depth;
  const double xc = zc / std::tan(rad(s.plane_dip));     // the crack's x
  const double xcrest = h / std::tan(rad(s.face_dip));
  const double xtop = h / std::tan(rad(s.plane_dip));     // the plane meets the top surface
  json scene = scene_base(s.unit_weight, 0.005, 1.0);
  // Blocks: 0 the rock under the plane (its plane edge from 10 m beyond the toe up to the top
  // surface, so no vertex of it touches the sliding block's base); 1 the wedge of rock behind
  // the crack, above the plane's continuation; 2 the sliding block.
  const P toe{0.0, 0.0}, bottom{xc, zc}, top{xc, h}, crest{xcrest, h};
  const P below = along(-10.0, s.plane_dip), far{xtop + 40.0, h}, end{xtop, h};
  add_block(scene, {below, {below.x, -30.0}, {far.x, -30.0}, far, end}, true);
  add_block(scene, {bottom, end, top}, true);
  add_block(scene, {toe, bottom, top, crest}, false);
  // The plane: c, phi, and a tensile strength equal to c, so that a two-point share of the
  // normal force that pulls one end (the block's moment balance) does not break the bond
  // limit equilibrium assumes intact; it adds no shear strength. The crack: no strength, it
  // only carries water.
  scene["joint_materials"] = {{"default", joint(s.friction_angle, s.cohesion * 1e3, s.cohesion * 1e3)},
                              {"crack", joint(0.0, 0.0, 0.0)}};
  scene["joints"] = {{{"blocks", {1, 2}}, {"material", "crack"}}};
  c.title = "Hoek & Bray tension crack, H 60 m, face 50, plane 35, crack 14 m";
  if (water_depth > 0.0) {
    // A straight phreatic line from the toe to zw above the crack's bottom, flat beyond: in the
    // crack p = gamma_w (zc + zw - y), hydrostatic to gamma_w zw at its bottom; along the plane
    // y = x tan psi it gives gamma_w zw x / xc, linear from the toe, as Hoek & Bray's U.
    scene["water"] = {{"phreatic_line", {{0.0, 0.0}, {xc, zc + water_depth}}}, {"unit_weight", kWaterWeight}};
    c.needs_water = true;
    c.title += water_depth < s.crack_depth ? ", crack half full" : ", crack full";
  } else {
    c.title += ", dry";
  }
  c.scene = scene.dump();
  return c;
}

// ---- case 2b: the dry tension-crack slope held by a tensioned bolt ----
// One bolt (per metre of slope: a row of bolts at 1 m spacing) from the face into the rock
// under the plane, dipping `bolt_dip` below the horizontal, whose tension T brings the limit-
// equilibrium factor to `target`: F = (c A + (N + T_n) tan phi) / (D - T_s) solved for T.
// Tensioned (`passive` false), the bolt is tensioned to T and yields at T (a cable anchor
// held at its working load), so its force is T while the block slides: the limit-equilibrium
// free body's. Passive, it starts at no force and yields at T (its force at the limit is T
// again), and is stiff: k = 1e10 N/m, 0.2 mm to its capacity. A static step moves the block
// against its inertia 2M/dt^2, so a bolt of stiffness k loads over about 2M/(k dt^2) steps:
// at 1e9 N/m and dt / 5 that is some 3000 steps, longer than a trial, whose block then crept
// too slowly to be called failing (1.5977 found, against 1.5039 at the other settings).
SlopeCase bolted_hoek_bray_case(const std::string& name, bool passive, double target,
                                double bolt_dip, double a_det) {
  const TensionCrackSlope s = hoek_bray_slope(0.0);
  PlaneBlock pb = tension_crack_block(s);
  const double psi = rad(pb.dip), beta = rad(bolt_dip);
  // The bolt's direction from the block to the anchor: into the slope (+x) and down.
  const P e{std::cos(beta), -std::sin(beta)};
  const double along = e.x * std::cos(psi) + e.y * std::sin(psi);   // up the plane
  const double normal = e.x * std::sin(psi) - e.y * std::cos(psi);  // into the plane
  const double tan_phi = std::tan(rad(pb.friction_angle));
  const double n0 = pb.weight * std::cos(psi), d0 = pb.weight * std::sin(psi);
  const double tension = (target * d0 - pb.cohesion * pb.length - n0 * tan_phi) /
                         (normal * tan_phi + target * along);
  pb.bolt_normal = tension * normal;
  pb.bolt_along = tension * along;
  SlopeCase c = hoek_bray_case(name, 0.0, 0.0, a_det);
  c.le_factor = plane_factor(pb);
  c.resolution = resolution_of([&](double f) { return plane_out_of_balance(pb, f); }, c.le_factor,
                               pb.weight, a_det);
  json scene = json::parse(c.scene);
  // From the middle of the face, 20 m along the bolt: through the plane into block 0.
  const double h = s.height, xcrest = h / std::tan(rad(s.face_dip));
  const P from{0.5 * xcrest + 0.5, 0.5 * h};
  const P to{from.x + 20.0 * e.x, from.y + 20.0 * e.y};
  const double t_newton = tension * 1e3;
  scene["bolts"] = {{{"name", "row"},
                     {"from", {from.x, from.y}},
                     {"to", {to.x, to.y}},
                     // Tensioned: 200 GPa steel, 5 cm^2 per metre of slope, 20 m free, E A / L.
                     {"stiffness", passive ? 1e10 : 200e9 * 5e-4 / 20.0},
                     {"pretension", passive ? 0.0 : t_newton},
                     {"yield_force", t_newton}}};
  c.scene = scene.dump();
  char title[200];
  std::snprintf(title, sizeof title,
                "Hoek & Bray tension crack, dry, bolted (%s): T = %.0f kN/m at %.0f deg below "
                "the horizontal, for F = %.2f",
                passive ? "passive, yielding at T" : "tensioned to T", tension, bolt_dip, target);
  c.title = title;
  return c;
}

// ---- case 2c: a deep tension crack, cut by dda cut from the profile and two joints ----
// H 60 m, face 80, plane 35 (c 50 kPa, phi 35, tensile strength c as in case 2), a vertical
// crack 45 m deep with no strength: the crack (45 m) is longer than the plane (26.2 m), so
// one joint material per pair of blocks, taken from the longest shared boundary, gave the
// plane the crack's and the block slid at any strength. Each contact takes the material of
// the joint its edge lies on (Block::edge_joints): the plane's strength, F by the closed
// form of a block on a plane.
SlopeCase deep_crack_cut_case(double a_det) {
  const double h = 60.0, face = 80.0, crack = 45.0, unit_weight = 26.0;
  PlaneBlock pb;
  pb.dip = 35.0;
  pb.friction_angle = 35.0;
  pb.cohesion = 50.0;
  pb.length = (h - crack) / std::sin(rad(pb.dip));
  const double xcrest = h / std::tan(rad(face)), xc = (h - crack) / std::tan(rad(pb.dip));
  pb.weight = unit_weight * area({{0.0, 0.0}, {xc, h - crack}, {xc, h}, {xcrest, h}});
  SlopeCase c;
  c.name = "deep_crack_cut";
  c.le_factor = plane_factor(pb);
  c.resolution = resolution_of([&](double f) { return plane_out_of_balance(pb, f); }, c.le_factor,
                               pb.weight, a_det);
  json model = scene_base(unit_weight, 0.005, 1.0);
  model.erase("blocks");
  model["material"] = "rock";
  const P front = along(-20.0, pb.dip);  // the ground in front of the toe: the plane's line
  model["domain"] = polygon({front, {front.x, -30.0}, {150.0, -30.0}, {150.0, h}, {xcrest, h}, {0.0, 0.0}});
  model["fixed"] = {{"edges", {1}}};
  model["joint_materials"] = {{"default", joint(pb.friction_angle, 50e3, 50e3)},
                              {"plane", joint(pb.friction_angle, 50e3, 50e3)},
                              {"crack", joint(0.0, 0.0, 0.0)}};
  model["joints"] = {{{"from", pt({0.0, 0.0})}, {"to", pt({xc, h - crack})}, {"joint_material", "plane"}},
                     {{"from", pt({xc, h - crack})}, {"to", pt({xc, h + 1.0})}, {"joint_material", "crack"}}};
  const Model m = parse_model_text(model.dump(), "deep_crack_cut model");
  c.scene = cut_scene(m, cut_model(m.spec), "").scene.dump();
  c.title = "deep tension crack cut from a profile: H 60 m, face 80, plane 35, crack 45 m "
            "(longer than the plane), dry";
  return c;
}

// ---- case 2d: the deep-crack block on a plane of finite persistence, its rock bridges cut ----
// The profile and crack of case 2c, the plane now a joint set of one line through the toe:
// traces 10 m long (phi 35, no cohesion) with rock bridges of 4 m between them (a random
// phase from the seed), the bridges of their own material (bridge_material: phi 35, c 500
// kPa, tensile strength c, Coulomb slip so that they keep c while sliding, as limit
// equilibrium assumes), smeared over the block's base by their share of it. The plane's line runs on behind the crack to the top surface, so the
// rock above it there is a block too, fixed by a region. The closed form is a block on a
// plane with cohesion over the bridges' length alone: (c_b L_b + W cos psi tan phi) /
// (W sin psi), L_b the bridge edges of the sliding block as cut.
SlopeCase rock_bridge_cut_case(double a_det) {
  const double h = 60.0, face = 80.0, crack = 45.0, unit_weight = 26.0, c_bridge = 500.0;
  const double xcrest = h / std::tan(rad(face)), xc = (h - crack) / std::tan(rad(35.0));
  json model = scene_base(unit_weight, 0.005, 1.0);
  model.erase("blocks");
  model["material"] = "rock";
  const P front = along(-20.0, 35.0);
  model["domain"] = polygon({front, {front.x, -30.0}, {150.0, -30.0}, {150.0, h}, {xcrest, h}, {0.0, 0.0}});
  model["fixed"] = {{"edges", {1}},
                    {"polygon", polygon({{xc - 0.01, -40.0}, {200.0, -40.0}, {200.0, 70.0}, {xc - 0.01, 70.0}})}};
  model["joint_materials"] = {{"default", joint(35.0, 0.0, 0.0)},
                              {"plane", joint(35.0, 0.0, 0.0)},
                              {"bridge", joint(35.0, c_bridge * 1e3, c_bridge * 1e3)},
                              {"crack", joint(0.0, 0.0, 0.0)}};
  model["seed"] = 3;
  model["joint_sets"] = {{{"dip", 35.0}, {"spacing", 1000.0}, {"offset", 0.0}, {"trace_length", 10.0},
                          {"bridge", 4.0}, {"joint_material", "plane"}, {"bridge_material", "bridge"}}};
  // The crack from 1 m below the plane's line: the set's line passes through the toe and the
  // crack's foot only up to rounding, and a crack ending a hair short of it would be a dead
  // end (removed); the stub below the line is one.
  model["joints"] = {{{"from", pt({xc, h - crack - 1.0})}, {"to", pt({xc, h + 1.0})}, {"joint_material", "crack"}}};
  const Model m = parse_model_text(model.dump(), "rock_bridge_cut model");
  const CutModel cut = cut_model(m.spec);
  PlaneBlock pb;
  pb.dip = 35.0;
  pb.friction_angle = 35.0;
  pb.cohesion = c_bridge;
  for (std::size_t i = 0; i < cut.cut.blocks.size(); ++i) {
    if (cut.fixed[i]) continue;
    const Polygon& b = cut.cut.blocks[i];
    pb.weight = unit_weight * signed_area(b);
    for (std::size_t k = 0; k < b.size(); ++k) {
      const EdgeBridge& e = cut.edge_bridges[i][k];
      if (e.material == "bridge") pb.length += e.share * (b[(k + 1) % b.size()] - b[k]).norm();
    }
  }
  SlopeCase c;
  c.name = "rock_bridge_cut";
  c.le_factor = plane_factor(pb);
  c.resolution = resolution_of([&](double f) { return plane_out_of_balance(pb, f); }, c.le_factor,
                               pb.weight, a_det);
  c.scene = cut_scene(m, cut, "").scene.dump();
  char title[200];
  std::snprintf(title, sizeof title,
                "rock bridges cut: the deep-crack block on a plane of 10 m traces and 4 m "
                "bridges (c %.0f kPa), %.2f m of bridge under the block",
                c_bridge, pb.length);
  c.title = title;
  return c;
}

// ---- case 3: active-passive wedge (Wyllie & Mah 2004, ch. 7) ----
// The kink K at the origin; the upper plane at 50 degrees, the lower at 10. The vertical
// interface meets the upper plane 1 m above K (at K2), not at K: a rigid upper wedge whose
// corner sat at K would drive that corner into the rock under the lower plane; from K2 it
// slides down the upper plane while the lower wedge's 1 m sliver on it lifts off (the two
// wedges' horizontal speeds match across the interface), so the mechanism limit equilibrium
// assumes is admissible for rigid blocks.
SlopeCase wedge_case(const std::string& name, double interface_friction, double published,
                     double a_det) {
  const BiplanarWedge w = biplanar_wedge(interface_friction);
  SlopeCase c;
  c.name = name;
  c.published = published;
  c.le_factor = wedge_factor(w);
  c.resolution = resolution_of([&](double f) { return wedge_out_of_balance(w, f); }, c.le_factor,
                               w.upper_weight + w.lower_weight, a_det);
  const double unit_weight = 25.0;
  const double area_each = w.upper_weight / unit_weight;  // 40 m^2
  const P k{0.0, 0.0}, k2 = along(1.0, w.upper_dip);
  // Upper wedge: the triangle K2, U, J with a horizontal top; legs d and d tan(a1).
  const double d = std::sqrt(2.0 * area_each / std::tan(rad(w.upper_dip)));
  const P u{k2.x + d, k2.y + d * std::tan(rad(w.upper_dip))}, j{k2.x, u.y};
  // Lower wedge: T, K, K2, J; T on the lower plane, as far as its area requires (linear in it).
  const double area_k = area({k, k2, j});
  const P unit = along(-1.0, w.lower_dip);
  const double t_dist = (area_each - area_k) / (0.5 * (j.x * unit.y - unit.x * j.y));
  const P t{unit.x * t_dist, unit.y * t_dist};
  json scene = scene_base(unit_weight, 0.005, 1.0);
  const P t_far = along(-10.0 - t_dist, w.lower_dip);
  const P u_far{u.x + 4.0 * std::cos(rad(w.upper_dip)), u.y + 4.0 * std::sin(rad(w.upper_dip))};
  add_block(scene, {t_far, {t_far.x, -20.0}, {u_far.x + 20.0, -20.0}, {u_far.x + 20.0, u_far.y}, u_far, k}, true);
  add_block(scene, {t, k, k2, j}, false);
  add_block(scene, {k2, u, j}, false);
  scene["joint_materials"] = {{"default", joint(w.friction_angle, 0.0, 0.0)},
                              {"interface", joint(interface_friction, 0.0, 0.0)}};
  scene["joints"] = {{{"blocks", {1, 2}}, {"material", "interface"}}};
  c.title = "active-passive wedge, planes 50 and 10, phi 30, interface " +
            (interface_friction > 0.0 ? "phi " + std::to_string(static_cast<int>(interface_friction))
                                      : std::string("frictionless"));
  c.scene = scene.dump();
  return c;
}

// ---- case 4: Goodman and Bray's toppling example (Hoek & Bray 1981, ch. 9) ----
// Built in the frame of the steps (x up the base dip, y up the columns), turned by psi_p: the
// columns are the tabular method's rectangles, column n over [(n-1) dx, n dx] from its step
// (n-1) b up to y_n. The fixed rock's risers stand 1 cm upslope of the column sides (at
// n dx + 0.01): a column's toe corner then overhangs the step's edge by 1 cm instead of sitting
// on a corner shared by three blocks, where the contact rule would have to break a tie between
// the tread and the riser. The 1 cm moves each column's pivot by 0.1 % of its width.
SlopeCase topple_case(double a_det) {
  const ToppleSlope s = goodman_bray_slope();
  SlopeCase c;
  c.name = "toppling";
  c.title = "Goodman & Bray toppling, 16 columns 10 m, steps at 30, phi 45";
  c.limiting_friction = limiting_friction_angle(s);
  c.le_factor = topple_factor(s, kToppleFriction);
  c.published = std::tan(rad(kToppleFriction)) / std::tan(rad(38.15));
  c.published_decimals = 2;
  const std::vector<double> y = column_heights(s);
  const ToppleSolution le = topple_at(s, c.limiting_friction);
  double moving = 0.0;
  for (std::size_t n = 0; n < y.size(); ++n) {
    c.le_modes.push_back(mode_name(le.modes[n]));
    if (le.modes[n] != ColumnMode::Stable) moving += s.unit_weight * y[n] * s.width;
  }
  const double tan_phi = std::tan(rad(kToppleFriction));
  c.resolution = resolution_of(
      [&](double f) { return topple_at(s, std::atan(tan_phi / f) * 180.0 / kPi).toe_force; },
      c.le_factor, moving, a_det);
  const double cs = std::cos(rad(s.base_dip)), sn = std::sin(rad(s.base_dip));
  auto g = [&](double x, double yy) { return P{x * cs - yy * sn, x * sn + yy * cs}; };
  json scene = scene_base(s.unit_weight, 0.005, 1.0);
  const double inset = 0.01, dx = s.width;
  const int n_cols = s.columns;
  std::vector<P> base = {g(-10.0, -30.0), g(n_cols * dx + 10.0, -30.0),
                         g(n_cols * dx + 10.0, (n_cols - 1) * s.b)};
  for (int n = n_cols - 1; n >= 1; --n) {  // from the top step down: tread, then riser
    base.push_back(g(n * dx + inset, n * s.b));
    base.push_back(g(n * dx + inset, (n - 1) * s.b));
  }
  base.push_back(g(-10.0, 0.0));
  add_block(scene, base, true);
  for (int n = 1; n <= n_cols; ++n) {
    const double x0 = (n - 1) * dx, x1 = n * dx, yb = (n - 1) * s.b;
    const double h = y[static_cast<std::size_t>(n - 1)];
    // Toe-side base corner first: the mode classification reads vertices 0 (pivot) and 3.
    add_block(scene, {g(x0, yb), g(x1, yb), g(x1, yb + h), g(x0, yb + h)}, false);
    c.columns.push_back(n);
  }
  scene["joint_materials"] = {{"default", joint(kToppleFriction, 0.0, 0.0)}};
  c.scene = scene.dump();
  return c;
}

}  // namespace

PlaneBlock planar_block(double cohesion_kpa, double uplift_kn) {
  PlaneBlock b;
  b.weight = 1000.0;
  b.dip = 30.0;
  b.friction_angle = 30.0;
  b.cohesion = cohesion_kpa;
  b.length = 10.0;
  b.uplift = uplift_kn;
  return b;
}

// H 60 m, face 50, plane 35, crack 14 m deep, c 50 kPa, phi 35. Hoek & Bray work in tonnes
// (rock 2.6 t/m^3, water 1.0); 26 and 9.81 kN/m^3 reproduce their published factors (with
// 10 kN/m^3 for water the full crack would give 0.923).
TensionCrackSlope hoek_bray_slope(double water_depth) {
  TensionCrackSlope s;
  s.height = 60.0;
  s.face_dip = 50.0;
  s.plane_dip = 35.0;
  s.crack_depth = 14.0;
  s.water_depth = water_depth;
  s.unit_weight = 26.0;
  s.water_unit_weight = 9.81;
  s.friction_angle = 35.0;
  s.cohesion = 50.0;
  return s;
}

BiplanarWedge biplanar_wedge(double interface_friction) {
  BiplanarWedge w;
  w.upper_weight = w.lower_weight = 1000.0;
  w.upper_dip = 50.0;
  w.lower_dip = 10.0;
  w.friction_angle = 30.0;
  w.interface_friction = interface_friction;
  return w;
}

// Hoek & Bray's table uses a1 = 5.0, a2 = 5.0, b = 1.0 m (dx 10 m): heights 4, 8, ..., 40 to
// the crest, then 34, 28, ..., 4. These are the angles' values rounded to 0.1 m (face 56.6,
// steps 30, overall base 35.8 give a1 5.01, b 1.02; an upper slope of 4 degrees a2 4.88); the
// limiting angle 38.15 is the rounded table's (the unrounded 38.15 to 38.19 depending on the
// base angle taken).
ToppleSlope goodman_bray_slope() { return ToppleSlope{}; }

std::vector<SlopeCase> all_cases(double a_det) {
  std::vector<SlopeCase> cases;
  cases.push_back(planar_case("planar_c0", 0.0, 0.0, 1.000, a_det));
  cases.push_back(planar_case("planar_c10", 10.0, 0.0, 1.200, a_det));
  cases.back().in_smoke = true;
  cases.push_back(planar_case("planar_uplift", 10.0, 200.0, 0.969, a_det));
  // No published value: the closed form only (published 0 is printed as none).
  cases.push_back(planar_case("planar_seismic", 10.0, 0.0, 0.0, a_det, 0.1));
  cases.push_back(hoek_bray_case("hoek_bray_dry", 0.0, 1.292, a_det));
  cases.back().in_smoke = true;
  cases.push_back(hoek_bray_case("hoek_bray_half", 7.0, 1.128, a_det));
  cases.push_back(hoek_bray_case("hoek_bray_full", 14.0, 0.930, a_det));
  // No published value: the closed form only.
  cases.push_back(bolted_hoek_bray_case("hoek_bray_bolted", false, 1.5, 20.0, a_det));
  cases.push_back(bolted_hoek_bray_case("hoek_bray_passive_bolt", true, 1.5, 20.0, a_det));
  // No published value: the closed form only.
  cases.push_back(deep_crack_cut_case(a_det));
  cases.push_back(rock_bridge_cut_case(a_det));
  cases.push_back(wedge_case("wedge_smooth", 0.0, 1.000, a_det));
  cases.push_back(wedge_case("wedge_rough", 30.0, 1.147, a_det));
  cases.push_back(topple_case(a_det));
  return cases;
}

}  // namespace dda::slope
