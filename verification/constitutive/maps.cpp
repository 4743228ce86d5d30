#include "maps.hpp"

#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>

#include "materials/elastic.hpp"
#include "materials/principal.hpp"
#include "materials/yield_drucker_prager.hpp"
#include "materials/yield_mohr_coulomb.hpp"

namespace dda::constitutive {

namespace {

// A rock-like material: E = 20 GPa, nu = 0.3, c = 1 MPa, phi = 30 degrees. The errors are
// relative, so only nu and phi (and psi) shape the maps; nu = 0.3 rather than 0.25 keeps
// lambda != G, which with phi = 30 degrees makes some paths exactly neutral.
constexpr double kYoung = 20e9;
constexpr double kPoisson = 0.3;
constexpr double kCohesion = 1e6;
constexpr double kFriction = 30.0;
constexpr double kDilationNonAssociated = 10.0;

double rad(double deg) { return deg * std::numbers::pi / 180.0; }

MaterialParameters material(MaterialModel model, double dilation) {
  MaterialParameters p;
  p.young = kYoung;
  p.poisson = kPoisson;
  p.density = 2500.0;
  if (model == MaterialModel::MohrCoulomb) {
    p.model_parameters = plastic_parameters<MohrCoulombParameters>(kCohesion, kFriction, dilation);
  } else {
    DruckerPragerParameters dp = plastic_parameters<DruckerPragerParameters>(kCohesion, kFriction, dilation);
    dp.match = DruckerPragerMatch::PlaneStrain;
    p.model_parameters = dp;
  }
  return p;
}

double yield_strain() {
  const ElasticModuli m = elastic_moduli(kYoung, kPoisson);
  return kCohesion * std::cos(rad(kFriction)) / (2.0 * m.shear);
}

// The major principal stress on the main Mohr-Coulomb plane for a minor one s3:
// (s1 - s3) + (s1 + s3) sin(phi) = 2 c cos(phi).
double mc_major(double s3) {
  const double sp = std::sin(rad(kFriction)), cp = std::cos(rad(kFriction));
  return ((1.0 - sp) * s3 + 2.0 * kCohesion * cp) / (1.0 + sp);
}

// A Drucker-Prager stress on the cone at mean stress p: deviator (q, -q, 0) in (xx, yy, zz),
// so sqrt(J2) = q = xi c - eta p.
Vec4 dp_on_cone(double p) {
  const DruckerPragerCoefficients k =
      drucker_prager_coefficients(DruckerPragerMatch::PlaneStrain, kFriction, kFriction);
  const double q = k.xi * kCohesion - k.eta * p;
  return {p + q, p - q, p, 0.0};
}

const Vec3 kDeviatoric{1.0, -1.0, 0.0};  // exx = -eyy: a pure deviator, szz unchanged
const Vec3 kVolumetric{1.0, 1.0, 0.0};   // exx = eyy (ezz = 0: not purely hydrostatic)
const Vec3 kShear{0.0, 0.0, 2.0};        // gxy = 2 exy: turns the principal axes

MapSpec map(std::string name, std::string title, std::string start, std::string flow,
            MaterialParameters params, const Vec4& s0, const Vec3& dy, std::string y_label) {
  MapSpec m;
  m.name = std::move(name);
  m.title = std::move(title);
  m.start = std::move(start);
  m.flow = std::move(flow);
  m.params = std::move(params);
  m.start_stress = s0;
  m.dir_x = kDeviatoric;
  m.dir_y = dy;
  m.x_label = "deviatoric (exx = -eyy) / e_y";
  m.y_label = std::move(y_label);
  m.yield_strain = yield_strain();
  return m;
}

}  // namespace

std::vector<MapSpec> make_maps() {
  const double c = kCohesion;
  const std::string vol = "in-plane volumetric (exx = eyy) / e_y";
  const std::string shear = "shear (exy = gxy / 2) / e_y";
  const std::string assoc = "associated (psi = phi = 30)";
  const std::string nonassoc = "non-associated (psi = 10)";
  const MaterialParameters mc = material(MaterialModel::MohrCoulomb, kFriction);
  const MaterialParameters mc_na = material(MaterialModel::MohrCoulomb, kDilationNonAssociated);
  const MaterialParameters dp = material(MaterialModel::DruckerPrager, kFriction);
  const MaterialParameters dp_na = material(MaterialModel::DruckerPrager, kDilationNonAssociated);

  // Mohr-Coulomb starts, sxx the major in-plane stress and syy the minor one, so that x > 0
  // loads outward. Main plane: s3 = -5c, szz halfway between s1 and s3.
  const double s3 = -5.0 * c, s1 = mc_major(s3);
  const Vec4 plane{s1, s3, 0.5 * (s1 + s3), 0.0};
  // Compression meridian (s1 = s2 > s3, tension positive): szz = sxx.
  const Vec4 compression{s1, s3, s1, 0.0};
  // Extension meridian (s1 > s2 = s3): szz = syy.
  const Vec4 extension{s1, s3, s3, 0.0};
  // Near the apex (c cot phi = 1.73c): s3 = c, s1 = 1.49c.
  const double a3 = 1.0 * c, a1 = mc_major(a3);
  const Vec4 near_apex{a1, a3, 0.5 * (a1 + a3), 0.0};
  // On the tension cut-off T = c/2 alone (Mohr-Coulomb inside: f = -0.48 c).
  MaterialParameters mc_t = mc;
  std::get<MohrCoulombParameters>(mc_t.model_parameters).tensile_strength = 0.5 * c;
  const Vec4 tension{0.5 * c, -1.0 * c, -0.25 * c, 0.0};
  // Softening: the cohesion falls linearly to c/2 at eps_p = 10 e_y, then stays.
  MaterialParameters mc_soft = mc;
  std::get<MohrCoulombParameters>(mc_soft.model_parameters).hardening = {
      {0.0, c}, {10.0 * yield_strain(), 0.5 * c}};

  std::vector<MapSpec> maps;
  maps.push_back(map("mc_plane_assoc", "Mohr-Coulomb, main plane",
                     "main plane (s3 = -5c, s2 = szz halfway)", assoc, mc, plane, kVolumetric, vol));
  maps.push_back(map("mc_plane_nonassoc", "Mohr-Coulomb, main plane",
                     "main plane (s3 = -5c, s2 = szz halfway)", nonassoc, mc_na, plane, kVolumetric,
                     vol));
  maps.push_back(map("mc_plane_shear_assoc", "Mohr-Coulomb, main plane, turning axes",
                     "main plane (s3 = -5c, s2 = szz halfway)", assoc, mc, plane, kShear, shear));
  maps.push_back(map("mc_compression_edge_assoc", "Mohr-Coulomb, compression meridian",
                     "edge s1 = s2 = szz (s3 = -5c)", assoc, mc, compression, kVolumetric, vol));
  maps.push_back(map("mc_extension_edge_assoc", "Mohr-Coulomb, extension meridian",
                     "edge s2 = s3 = szz (s3 = -5c)", assoc, mc, extension, kVolumetric, vol));
  maps.push_back(map("mc_near_apex_assoc", "Mohr-Coulomb, near the apex",
                     "main plane near the apex (s3 = c, apex at 1.73c)", assoc, mc, near_apex,
                     kVolumetric, vol));
  maps.push_back(map("mc_tension_cutoff_assoc", "Mohr-Coulomb with tension cut-off T = c/2",
                     "cut-off s1 = T (MC inside)", assoc, mc_t, tension, kVolumetric, vol));
  maps.push_back(map("mc_plane_softening_assoc", "Mohr-Coulomb, main plane, cohesion softening",
                     "main plane (s3 = -5c), c -> c/2 at eps_p = 10 e_y", assoc, mc_soft, plane,
                     kVolumetric, vol));
  maps.push_back(map("dp_cone_assoc", "Drucker-Prager (plane-strain match), cone",
                     "cone at p = -3c, szz = p", assoc, dp, dp_on_cone(-3.0 * c), kVolumetric, vol));
  maps.push_back(map("dp_cone_nonassoc", "Drucker-Prager (plane-strain match), cone",
                     "cone at p = -3c, szz = p", nonassoc, dp_na, dp_on_cone(-3.0 * c),
                     kVolumetric, vol));
  maps.push_back(map("dp_cone_shear_assoc", "Drucker-Prager, cone, turning axes",
                     "cone at p = -3c, szz = p", assoc, dp, dp_on_cone(-3.0 * c), kShear, shear));
  maps.push_back(map("dp_near_apex_assoc", "Drucker-Prager, near the apex",
                     "cone at p = 1.2c (apex at 1.73c)", assoc, dp, dp_on_cone(1.2 * c),
                     kVolumetric, vol));
  return maps;
}

double stress_norm(const Vec4& s) {
  return std::sqrt(s[kXX] * s[kXX] + s[kYY] * s[kYY] + s[kZZ] * s[kZZ] + 2.0 * s[kXY] * s[kXY]);
}

double start_yield_residual(const MapSpec& spec) {
  if (const auto* mc = std::get_if<MohrCoulombParameters>(&spec.params.model_parameters)) {
    const MohrCoulombParameters& p = *mc;
    const MohrCoulombAngles a = mohr_coulomb_angles(p.friction_angle, p.dilation_angle);
    const Vec3 s = principal_stress(spec.start_stress).sorted();
    double f = mohr_coulomb_yield(s, p.cohesion, a);
    // On the cut-off alone, the distance to it is the residual.
    if (p.tensile_strength && f < 0.0) f = s[0] - *p.tensile_strength;
    return std::abs(f) / (p.cohesion * a.cos_phi);
  }
  const auto& p = std::get<DruckerPragerParameters>(spec.params.model_parameters);
  const DruckerPragerCoefficients k =
      drucker_prager_coefficients(p.match, p.friction_angle, p.dilation_angle);
  return std::abs(drucker_prager_yield(spec.start_stress, p.cohesion, k)) / (k.xi * p.cohesion);
}

Reference sub_incremented(const MapSpec& spec, const Vec3& strain, int substeps) {
  Reference ref;
  MaterialState state;
  for (int k = 1; k <= substeps; ++k) {
    const Vec3 e = strain * (static_cast<double>(k) / substeps);
    MaterialResult r = integrate(spec.params, state, e, spec.start_stress);
    if (!r.status.converged) {
      ref.ok = false;
      return ref;
    }
    state = r.state;
    ref.stress = r.stress;
    ref.branch = r.branch;
  }
  ref.eps_p = state.eps_p;
  return ref;
}

Vec3 grid_strain(const MapSpec& spec, double x, double y) {
  return spec.yield_strain * (x * spec.dir_x + y * spec.dir_y);
}

double map_error(const MaterialResult& one, const Reference& reference) {
  if (!one.status.converged || !reference.ok) return std::numeric_limits<double>::quiet_NaN();
  return stress_norm(one.stress - reference.stress) / stress_norm(reference.stress);
}

double one_call_error(const MapSpec& spec, const Vec3& strain, int substeps) {
  const MaterialResult one = integrate(spec.params, MaterialState{}, strain, spec.start_stress);
  return map_error(one, sub_incremented(spec, strain, substeps));
}

MapResult compute_map(const MapSpec& spec, int n, int substeps, double min_timing_s) {
  using clock = std::chrono::steady_clock;
  MapResult out;
  out.spec = spec;
  out.n = n;
  out.substeps = substeps;
  out.surface_residual = start_yield_residual(spec);
  const double h = 2.0 * spec.extent / (n - 1);
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      Point pt;
      // Exact zero in the middle (n odd), symmetric about it.
      pt.x = (i - (n - 1) / 2) * h;
      pt.y = (j - (n - 1) / 2) * h;
      pt.strain = grid_strain(spec, pt.x, pt.y);
      out.points.push_back(pt);
    }
  }
  const MaterialState start;

  // The one-call sweep: once untimed (warm caches; these are also the results), then
  // repeated until it has taken min_timing_s (at least once).
  double sink = 0.0;
  for (Point& pt : out.points) pt.one = integrate(spec.params, start, pt.strain, spec.start_stress);
  long calls = 0;
  const auto t0 = clock::now();
  double elapsed = 0.0;
  do {
    for (const Point& pt : out.points) {
      const MaterialResult r = integrate(spec.params, start, pt.strain, spec.start_stress);
      sink += r.stress[kXX];
    }
    calls += static_cast<long>(out.points.size());
    elapsed = std::chrono::duration<double>(clock::now() - t0).count();
  } while (elapsed < min_timing_s);
  out.ns_per_call = 1e9 * elapsed / static_cast<double>(calls);

  const auto t1 = clock::now();
  for (Point& pt : out.points) {
    const Reference ref = sub_incremented(spec, pt.strain, substeps);
    pt.reference = ref.stress;
    pt.reference_eps_p = ref.eps_p;
    pt.reference_branch = ref.branch;
    pt.reference_ok = ref.ok;
    pt.error = map_error(pt.one, ref);
    sink += ref.stress[kXX];
  }
  const double ref_s = std::chrono::duration<double>(clock::now() - t1).count();
  out.ns_per_reference_call =
      1e9 * ref_s / (static_cast<double>(out.points.size()) * static_cast<double>(substeps));

  // Keeps the timed loops from being optimised away (the sum is never NaN for finite stresses).
  if (std::isnan(sink)) out.ns_per_call = std::numeric_limits<double>::quiet_NaN();
  return out;
}

}  // namespace dda::constitutive
