// Tables 2 and 3 of the paper and the energy check: the octagon pinned off its centre,
// swinging under gravity, for every treatment. Diagonal lengths and strains against the
// block's principal strains at steps 200, 2000 and 5000; kinetic plus potential energy and
// the swing angle at every step.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "kinematics/types.hpp"
#include "options.hpp"
#include "treatments.hpp"

namespace dda::paper {

// The four diagonals AE, BF, CG, DH (vertex indices A = 0 ... H = 7).
inline constexpr std::array<const char*, 4> kDiagonalNames{"AE", "BF", "CG", "DH"};

struct DiagonalRecord {
  int step = 0;
  std::array<double, 4> length{}, strain{};  // current length (m) and L/L0 - 1
  Vec3 block_strain = Vec3::Zero();          // [exx, eyy, gxy], global frame
  double e_max = 0.0, e_min = 0.0;           // principal strains (correct Eq. 22)
  bool all_between = false;                  // every diagonal strain within [e_min, e_max]
  double area_rel_change = 0.0;              // A / A0 - 1
};

struct EnergySample {
  int step = 0;
  double time = 0.0;
  double kinetic = 0.0, potential = 0.0;  // J per metre
  double pin = 0.0;                       // the pin spring's stored energy 1/2 p |x - X|^2
  double strain = 0.0;                    // elastic strain energy of the block
  double swing = 0.0;                     // angle swept by pin -> centroid since the start (rad)
};

struct SwingRun {
  std::string treatment;
  RunResult result;
  std::vector<DiagonalRecord> records;
  std::vector<EnergySample> energy;  // every step
  double max_swing = 0.0;            // largest |swing| (rad)
  double swing_tolerance = 0.0;      // rad; see swinging_octagon.cpp
  bool past_pi = false;
  double max_excess = 0.0;           // max over t of E(t) - E0 - pin(t) (J)
  double energy_tolerance = 0.0;     // J; see swinging_octagon.cpp
  double mgl = 0.0;                  // m g l (J per metre): the energy scale of the swing
  bool gains_energy = false;
};

std::vector<SwingRun> run_swinging(const Options& opt);

// swinging_diagonals.csv, swinging_strains.csv, swinging_energy.csv, swinging_summary.csv.
void write_swinging_csv(const Options& opt, const std::vector<SwingRun>& runs);

// The Tables 2-3 and energy sections of the report (markdown).
std::string swinging_report(const Options& opt, const std::vector<SwingRun>& runs);

// Principal strains of [exx, eyy, gxy] (engineering shear): the correct form of the paper's
// Eq. (22), (ex+ey)/2 +- sqrt(((ex-ey)/2)^2 + (gxy/2)^2) (docs/paper-errata.md, item 3). {max, min}.
std::array<double, 2> principal_strains(const Vec3& e);

}  // namespace dda::paper
