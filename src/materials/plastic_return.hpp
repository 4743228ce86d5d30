// What a return map hands back to integrate() (material.cpp): the stress and the tangent in
// 4-component form, eps_p, and how it got there. The plastic strain is not returned: it is
// e_p_start + D^-1 (s_trial - s) for every return, and integrate() computes it once.
#pragma once

#include "materials/material_types.hpp"
#include "materials/voigt4.hpp"

namespace dda {

struct PlasticReturn {
  Vec4 stress = Vec4::Zero();
  double eps_p = 0.0;
  Mat4 tangent = Mat4::Zero();  // d stress / d strain (4 x 4, engineering shear strain)
  Branch branch = Branch::Elastic;
  unsigned active_planes = 0;
  MaterialStatus status;
};

// The elastic outcome: the trial stress with the elastic tangent.
inline PlasticReturn elastic_return(const Vec4& trial, double eps_p, const Mat4& elastic) {
  PlasticReturn r;
  r.stress = trial;
  r.eps_p = eps_p;
  r.tangent = elastic;
  return r;
}

// A failed return: the trial stress, unchanged state, and why.
inline PlasticReturn failed_return(const Vec4& trial, double eps_p, const Mat4& elastic,
                                   std::string reason, double suggested_fraction) {
  PlasticReturn r = elastic_return(trial, eps_p, elastic);
  r.status.converged = false;
  r.status.reason = std::move(reason);
  r.status.suggested_fraction = suggested_fraction;
  return r;
}

// Relative tolerance of the returns' decisions (elastic or not, order kept, multipliers
// non-negative, inside the planes not in the active set), times a stress scale of the
// trial: 1e-12 of the largest stress, thousands of ulps above the round-off of a return (a
// handful of flops on 3-vectors), far below anything a tolerance could hide. Never a
// comparison with exact 0 (CalculiX bug #184, docs/closed-forms.md).
constexpr double kDecisionTolerance = 1e-12;

}  // namespace dda
