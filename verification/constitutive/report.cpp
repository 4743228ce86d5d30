#include "report.hpp"

#include "../common/format.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace dda::constitutive {

namespace {

using verification::full;
using verification::open_csv;
using verification::WholeFile;

// Two significant digits unless asked otherwise; NaN as "-".
std::string sig(double x, int digits = 2) { return verification::significant(x, digits); }

// A CSV text field in double quotes (RFC 4180: a quote inside is doubled).
std::string quoted(const std::string& text) {
  std::string q = "\"";
  for (const char ch : text) {
    if (ch == '"') q += '"';
    q += ch;
  }
  return q + '"';
}

std::string percent(double x) {
  if (std::isnan(x)) return "-";
  if (x == 0.0) return "0";
  char buf[32];
  if (x >= 1e-3) {
    std::snprintf(buf, sizeof buf, "%.2f %%", 100.0 * x);
  } else {
    std::snprintf(buf, sizeof buf, "%.1e", x);
  }
  return buf;
}

std::string grid_value(double v) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

// The cohesion table as "eps_p:cohesion;eps_p:cohesion;..." at full precision (no commas, so
// it stays one CSV field), or "none": check_projection.py rebuilds the softening from it.
std::string hardening_table(const FrictionalStrength& p) {
  if (p.hardening.empty()) return "none";
  std::string t;
  for (const HardeningPoint& h : p.hardening) {
    if (!t.empty()) t += ';';
    t += full(h.eps_p);
    t += ':';
    t += full(h.cohesion);
  }
  return t;
}

const char* match_name(DruckerPragerMatch m) {
  switch (m) {
    case DruckerPragerMatch::Outer:
      return "outer";
    case DruckerPragerMatch::Inner:
      return "inner";
    case DruckerPragerMatch::PlaneStrain:
      break;
  }
  return "plane_strain";
}

constexpr double kExact = 1e-12;  // "exact": a few thousand ulps of the stress

constexpr const char* kExplanation = R"(
## What the maps show

- **Elastic points are exact** (a convex domain: a trial inside it means the whole straight
  path stayed inside), so every map is 0 on its elastic side.
- **Mohr-Coulomb with fixed principal axes is exact on one face.** The faces are planes with a
  constant flow direction, so a return that ends on the face the path slid along is linear in
  the increment and the one call equals the sub-incremented path to round-off (including
  elastic-then-plastic paths, and the softening map while the path stays on one face: the
  cohesion table is linear in eps_p and the consistency condition only sees the end). This is
  why most plastic points of the `mc_*` volumetric maps are exact and why the error near zero
  increments is round-off there.
- **Errors come from a change of active set along the path.** Where the reference slides along
  a face to an edge (or across it into the neighbouring sextant, the principal order changing)
  or slides along the tension cut-off before reaching the Mohr-Coulomb plane, its plastic strain
  differs from that of the one call, which returns the end trial to one branch and cannot see
  the path. These errors are jumps rather than smooth in the increment: halving the worst
  increment usually drops the error to round-off (table below). The worst points lie at x < 0
  (the deviator reversed, the path crossing the elastic domain and reaching the surface on
  another face) with tensile y, where the stresses are small (||s*|| of the order of c): the
  absolute column says how large the errors are against the strength.
- **The Drucker-Prager cone is curved** in the deviatoric plane: the error grows smoothly, as
  h^2 (order about 2 below), and is 0 on the radial line y = 0 (dx is along the start's
  deviator) and in the apex region with perfect plasticity (the apex is one point).
- **Turning principal axes** (the shear maps): the principal-space returns keep the trial's
  axes while the sub-incremented path turns them gradually; the error is smooth, second order,
  and nearly the same for Mohr-Coulomb and Drucker-Prager because it is the rotation that
  dominates.
- **Near an apex** the start's Mohr-circle radius (about 0.25 c for both near-apex starts) is
  comparable to what an increment of 0.25 e_y adds to it (0.22 c): the Mohr-Coulomb return
  reaches an edge already on the first grid ring, and the Drucker-Prager deviator turns by a
  large angle in one increment (a small cone radius is a strongly curved surface), so the
  first ring already shows errors of about 1 %.
- **The reference's own accuracy.** Where the path changes active set, each sub-increment
  that crosses the change makes a first-order error of its own, so s* is good to about 1e-4
  there (the last column below: 1000 against 4000 sub-increments); smaller differences in
  those zones are not resolved. Where the one call is exact, so is every sub-increment.
- For every map, `check_projection.py` (run by `run.sh`) recomputes the one call, the
  reference and eps_p at the worst point and at four points of every branch from the
  equations, without the library (numpy: Mohr-Coulomb by every active set of its six planes
  and the cut-off in the trial's principal axes, the cohesion table solved segment by
  segment; Drucker-Prager in closed form): see `projection_check.md`.
)";

}  // namespace

MapSummary summarise(const MapResult& r) {
  MapSummary s;
  const Point* worst = nullptr;
  for (const Point& p : r.points) {
    ++s.count[static_cast<int>(p.one.branch)];
    if (!p.one.status.converged) ++s.failed_one;
    if (!p.reference_ok) ++s.failed_reference;
    if (std::isnan(p.error)) continue;
    if (p.one.branch != Branch::Elastic) {
      ++s.plastic;
      if (p.error <= kExact) ++s.exact;
    }
    if (worst == nullptr || p.error > worst->error) worst = &p;
    if (p.error > 0.01) ++s.above_1pct;
    s.max_absolute =
        std::max(s.max_absolute,
                 stress_norm(p.one.stress - p.reference) / frictional_strength(r.spec.params)->cohesion);
    const double reach = std::max(std::abs(p.x), std::abs(p.y));
    if (reach <= 1.0 + 1e-12) s.max_within_1 = std::max(s.max_within_1, p.error);
    if (reach <= 0.25 + 1e-12) s.max_within_025 = std::max(s.max_within_025, p.error);
  }
  if (worst == nullptr) {
    s.max_error = std::nan("");
    return s;
  }
  s.max_error = worst->error;
  s.max_x = worst->x;
  s.max_y = worst->y;
  s.max_branch = worst->one.branch;
  s.max_ref_branch = worst->reference_branch;
  for (int k = 0; k <= 6; ++k)
    s.scaled_errors.push_back(
        one_call_error(r.spec, worst->strain / std::ldexp(1.0, k), r.substeps));
  const Reference fine = sub_incremented(r.spec, worst->strain, 4 * r.substeps);
  s.reference_check = fine.ok ? stress_norm(worst->reference - fine.stress) / stress_norm(fine.stress)
                              : std::nan("");
  return s;
}

void write_map_csv(const std::filesystem::path& dir, const MapResult& r) {
  WholeFile out = open_csv(
      dir, r.spec.name + ".csv",
      "x,y,exx,eyy,gxy,sxx,syy,szz,sxy,ref_sxx,ref_syy,ref_szz,ref_sxy,error,branch,"
      "reference_branch,eps_p,reference_eps_p,status");
  for (const Point& p : r.points) {
    out << full(p.x) << ',' << full(p.y);
    for (int k = 0; k < 3; ++k) out << ',' << full(p.strain[k]);
    for (int k = 0; k < 4; ++k) out << ',' << full(p.one.stress[k]);
    for (int k = 0; k < 4; ++k) out << ',' << full(p.reference[k]);
    const char* status = !p.one.status.converged ? "one_call_failed"
                         : !p.reference_ok       ? "reference_failed"
                                                 : "ok";
    out << ',' << full(p.error) << ',' << branch_name(p.one.branch) << ','
        << branch_name(p.reference_branch) << ',' << full(p.one.state.eps_p) << ','
        << full(p.reference_eps_p) << ',' << status << '\n';
  }
  out.finish();  // throws "cannot write PATH" when a write, the close or the rename failed
}

void write_summary_csv(const std::filesystem::path& dir, const std::vector<MapResult>& maps,
                       const std::vector<MapSummary>& summaries) {
  WholeFile out = open_csv(dir, "maps.csv",
                           "name,title,start,flow,x_label,y_label,extent,n,substeps,"
                           "yield_strain,max_error,max_x,max_y,ns_per_call,"
                           "ns_per_reference_call,model,young,poisson,cohesion,"
                           "friction_angle,dilation_angle,tensile_strength,hardening,match,"
                           "start_sxx,start_syy,start_szz,start_sxy,dx_exx,dx_eyy,dx_gxy,"
                           "dy_exx,dy_eyy,dy_gxy");
  for (std::size_t i = 0; i < maps.size(); ++i) {
    const MapResult& r = maps[i];
    const MapSummary& s = summaries[i];
    out << quoted(r.spec.name) << ',' << quoted(r.spec.title) << ',' << quoted(r.spec.start) << ','
        << quoted(r.spec.flow) << ',' << quoted(r.spec.x_label) << ',' << quoted(r.spec.y_label)
        << ',' << full(r.spec.extent) << ',' << r.n
        << ',' << r.substeps << ',' << full(r.spec.yield_strain) << ',' << full(s.max_error)
        << ',' << full(s.max_x) << ',' << full(s.max_y) << ',' << full(r.ns_per_call) << ','
        << full(r.ns_per_reference_call);
    // A column another model has no parameter for is left empty (tensile_strength for
    // Drucker-Prager, match for Mohr-Coulomb).
    const MaterialParameters& m = r.spec.params;
    const FrictionalStrength& p = *frictional_strength(m);
    const auto* mc = std::get_if<MohrCoulombParameters>(&m.model_parameters);
    const auto* dp = std::get_if<DruckerPragerParameters>(&m.model_parameters);
    out << ',' << model_name(m.model()) << ',' << full(m.young) << ',' << full(m.poisson) << ','
        << full(p.cohesion) << ',' << full(p.friction_angle) << ',' << full(p.dilation_angle)
        << ',' << (mc && mc->tensile_strength ? full(*mc->tensile_strength) : std::string())
        << ',' << hardening_table(p) << ',' << (dp ? match_name(dp->match) : std::string());
    for (int k = 0; k < 4; ++k) out << ',' << full(r.spec.start_stress[k]);
    for (int k = 0; k < 3; ++k) out << ',' << full(r.spec.dir_x[k]);
    for (int k = 0; k < 3; ++k) out << ',' << full(r.spec.dir_y[k]);
    out << '\n';
  }
  out.finish();
}

std::string full_report(const Options& opt, const std::vector<MapResult>& maps,
                        const std::vector<MapSummary>& summaries, double wall_s) {
  std::ostringstream o;
  const double h = maps.empty() ? 0.0 : 2.0 * maps[0].spec.extent / (opt.n - 1);
  o << "# Iso-error maps of the return maps\n\n";
  o << "Relative stress error ||s - s*|| / ||s*|| (tensor norm: the shear counts twice) of ONE "
       "call to `integrate()` against a reference of "
    << opt.substeps
    << " equal sub-increments (successive calls with the state carried), from a stress on the "
       "yield surface, over a "
    << opt.n << " x " << opt.n << " grid of strain increments e_y (x dx + y dy), x and y in [-"
    << grid_value(maps.empty() ? 0.0 : maps[0].spec.extent) << ", "
    << grid_value(maps.empty() ? 0.0 : maps[0].spec.extent) << "] step " << grid_value(h)
    << (opt.smoke ? " (smoke run: a coarse grid)" : "") << ".\n\n";
  if (!maps.empty()) {
    o << "Material: E = 20 GPa, nu = 0.3, c = 1 MPa, phi = 30 degrees, plane strain; "
         "e_y = c cos(phi) / (2G) = "
      << sig(maps[0].spec.yield_strain, 3)
      << " (x = 1 along dx raises the Mohr-circle radius by c cos(phi), the shear strength at "
         "zero mean stress). dx = (exx, eyy, gxy) = (1, -1, 0): a pure deviator in the start's "
         "principal axes, x > 0 loading outward; dy = (1, 1, 0) (in-plane volumetric; with "
         "ezz = 0 it carries a deviatoric part) or (0, 0, 2) (shear exy, turning the principal "
         "axes). Drucker-Prager is matched to the same phi and c in plane strain.\n\n";
  }

  o << "## Maximum errors\n\n";
  o << "| map | start on the surface | flow | max error | at (x, y) | branch there (one call / "
       "reference end) | max, \\|x\\|,\\|y\\| <= 1 | max, \\|x\\|,\\|y\\| <= 0.25 | "
       "max \\|\\|s - s*\\|\\| / c | points > 1 % | plastic points exact (<= 1e-12) | "
       "failed (one / ref) |\n";
  o << "|---|---|---|---:|---|---|---:|---:|---:|---:|---:|---:|\n";
  for (std::size_t i = 0; i < maps.size(); ++i) {
    const MapResult& r = maps[i];
    const MapSummary& s = summaries[i];
    o << "| `" << r.spec.name << "` | " << r.spec.start << " | " << r.spec.flow << " | "
      << percent(s.max_error) << " | (" << grid_value(s.max_x) << ", " << grid_value(s.max_y)
      << ") | " << branch_name(s.max_branch) << " / " << branch_name(s.max_ref_branch) << " | "
      << percent(s.max_within_1) << " | " << percent(s.max_within_025) << " | "
      << sig(s.max_absolute) << " | " << s.above_1pct << " of " << r.points.size() << " | " << s.exact
      << " of " << s.plastic << " | " << s.failed_one << " / " << s.failed_reference << " |\n";
  }
  o << "\nOne-call branches over each grid (points):\n\n";
  o << "| map | elastic | plane | edge | apex | cone | tension |\n|---|---:|---:|---:|---:|---:|---:|\n";
  for (std::size_t i = 0; i < maps.size(); ++i) {
    o << "| `" << maps[i].spec.name << "` |";
    for (int b = 0; b < 6; ++b) o << ' ' << summaries[i].count[b] << " |";
    o << '\n';
  }

  o << kExplanation;

  o << "\n## Shrinking the worst increment\n\n";
  o << "The worst grid increment of each map scaled by 2^-k (the same direction), error of one "
       "call against the reference; the last column is the reference itself at the worst point "
       "against one with 4x the sub-increments (how far s* is from the exact solution).\n\n";
  o << "| map | k = 0 | 1 | 2 | 3 | 4 | 5 | 6 | order (k = 5 to 6) | reference check |\n";
  o << "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for (std::size_t i = 0; i < maps.size(); ++i) {
    const MapSummary& s = summaries[i];
    o << "| `" << maps[i].spec.name << "` |";
    for (double e : s.scaled_errors) o << ' ' << sig(e) << " |";
    std::string order = "-";
    if (s.scaled_errors.size() == 7 && s.scaled_errors[5] > kExact && s.scaled_errors[6] > 0.0)
      order = sig(std::log2(s.scaled_errors[5] / s.scaled_errors[6]), 3);
    o << ' ' << order << " | " << sig(s.reference_check) << " |\n";
  }

  o << "\n## Runtime\n\n";
  o << "Time per `integrate()` call: the one-call sweep over the grid (repeated for at least "
    << grid_value(opt.min_timing_s * 1e3)
    << " ms), and the reference's calls (mostly small increments, so more of them elastic or "
       "on one plane). `bench/bench_materials.cpp` gives the cost per branch.\n\n";
  o << "| map | ns per call (one call) | ns per call (reference) |\n|---|---:|---:|\n";
  for (const MapResult& r : maps)
    o << "| `" << r.spec.name << "` | " << sig(r.ns_per_call, 3) << " | "
      << sig(r.ns_per_reference_call, 3) << " |\n";
  o << "\nStart points on the surface: |f(start)| / strength <= ";
  double worst_residual = 0.0;
  for (const MapResult& r : maps) worst_residual = std::max(worst_residual, r.surface_residual);
  o << sig(worst_residual) << ". Wall time of this run: " << sig(wall_s, 3) << " s.\n";
  return o.str();
}

}  // namespace dda::constitutive
