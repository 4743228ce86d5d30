// Mohr-Coulomb return map with optional tension cut-off, in principal stress space with szz
// taking part (de Souza Neto, Peric and Owen 2008, section 8.2; docs/closed-forms.md).
#pragma once

#include "materials/elastic.hpp"
#include "materials/material_types.hpp"
#include "materials/plastic_return.hpp"

namespace dda {

// The return of `trial` (sxx, syy, szz, sxy) from eps_p_start. Active sets are tried in
// this order, the first that satisfies all return conditions is taken (non-negative
// multipliers, the trial's principal order kept, inside every plane not in the set):
//   main plane f_13;  tension s1 = T;  the edge that the sign of
//   (1 - sin psi) s1 - 2 s2 + (1 + sin psi) s3 picks, then the other one;
//   main plane with tension (corner);  s1 = s2 = T;  right edge with s1 = T;
//   the corner s1 = s2 = T on the left edge;  s1 = s2 = s3 = T;  the apex (f_13 = f_12 =
//   f_23 = 0).
// The corner s1 = s2 = T, f_13 = f_23 = 0 has four planes; a flow in their normal cone is a
// non-negative combination of three of them (Caratheodory), so its four three-plane subsets
// are tried. Its stress, plastic strain and eps_p are the same whichever is taken. The apex
// takes any sign of the single multipliers (only the plastic volume change must be >= 0),
// as de Souza Neto's apex return does. Sets with a tension plane are skipped without a
// cut-off. Every vertex and edge of the surface in sorted principal space is on the list.
//
// The apex needs phi > 0 and psi > 0: with psi = 0 a trial beyond it has no return (the
// flow has no volume change), and the status fails saying so (a cut-off below the apex
// avoids it).
PlasticReturn return_mohr_coulomb(const MohrCoulombParameters& p, const ElasticModuli& moduli,
                                  const Vec4& trial, double eps_p_start);

}  // namespace dda
