#include "kinsol_step.hpp"

#include <kinsol/kinsol.h>
#include <nvector/nvector_serial.h>
#include <sunlinsol/sunlinsol_klu.h>
#include <sunmatrix/sunmatrix_sparse.h>

#include <Eigen/Sparse>

#include "solver/assembly.hpp"
#include "solver/block_system.hpp"
#include "solver/contact_assembly.hpp"
#include "solver/material_coupling.hpp"

namespace dda {
namespace {

struct Problem {
  const World& world;
  std::vector<Contact> contacts;
  StepContext ctx;   // its loop points at `terms` (Problem is not copied)
  LoopTerms terms;   // the plastic blocks' linearisation at the iterate
  BlockSystem system;
  long residual_evals = 0;
};

// The step's system linearised at d: K d - f is then the residual at d (material_coupling.hpp:
// the linearised stress equals the material's own at the point of linearisation).
bool assemble_at(Problem& p, const Eigen::VectorXd& d) {
  p.terms.material_terms = start_linearization(p.world);
  if (follow_materials(p.world, d, p.terms.material_terms).failed) return false;
  p.ctx.loop = &p.terms;
  assemble(p.world, p.ctx, p.system);
  add_contact_terms(p.world, p.contacts, p.ctx, p.system);
  ++p.residual_evals;
  return true;
}

Eigen::Map<Eigen::VectorXd> view(N_Vector v) {
  return {N_VGetArrayPointer(v), static_cast<Eigen::Index>(N_VGetLength(v))};
}

int residual(N_Vector u, N_Vector r, void* data) {
  Problem& p = *static_cast<Problem*>(data);
  // KINSOL's unknowns are the dof map's (a rigid block's u0, v0, r0 only); the assembly
  // reads six slots per block. A failed return is recoverable: KINSOL may shorten the step.
  if (!assemble_at(p, p.system.expand(view(u)))) return 1;
  view(r) = p.system.full() * view(u) - p.system.reduce(p.system.rhs);
  return 0;
}

int jacobian(N_Vector u, N_Vector, SUNMatrix j, void* data, N_Vector, N_Vector) {
  Problem& p = *static_cast<Problem*>(data);
  if (!assemble_at(p, p.system.expand(view(u)))) return 1;
  Eigen::SparseMatrix<double> k = p.system.full();
  k.makeCompressed();
  const sunindextype nnz = k.nonZeros();
  if (SM_NNZ_S(j) < nnz && SUNSparseMatrix_Reallocate(j, nnz) != 0) return -1;
  for (Eigen::Index c = 0; c <= k.cols(); ++c) SM_INDEXPTRS_S(j)[c] = k.outerIndexPtr()[c];
  for (sunindextype i = 0; i < nnz; ++i) {
    SM_INDEXVALS_S(j)[i] = k.innerIndexPtr()[i];
    SM_DATA_S(j)[i] = k.valuePtr()[i];
  }
  return 0;
}

}  // namespace

KinsolStepResult solve_step_with_kinsol(const World& world, const std::vector<Contact>& contacts,
                                        const StepContext& ctx, double tolerance) {
  KinsolStepResult result;
  Problem problem{world, contacts, ctx, {}, {}, 0};
  problem.system.reset(rigid_rows(world));  // the dof map, for the number of unknowns
  const sunindextype n = problem.system.unknowns();
  SUNContext sunctx = nullptr;
  if (SUNContext_Create(nullptr, &sunctx) != 0) {
    result.message = "SUNContext_Create failed";
    return result;
  }
  N_Vector u = N_VNew_Serial(n, sunctx);
  N_Vector scale = N_VNew_Serial(n, sunctx);
  N_VConst(0.0, u);  // the step starts from zero increments
  N_VConst(1.0, scale);
  SUNMatrix jac = SUNSparseMatrix(n, n, 36 * n, CSC_MAT, sunctx);
  SUNLinearSolver ls = SUNLinSol_KLU(u, jac, sunctx);
  void* mem = KINCreate(sunctx);
  int flag = KINInit(mem, residual, u);
  if (flag == KIN_SUCCESS) flag = KINSetUserData(mem, &problem);
  if (flag == KIN_SUCCESS) flag = KINSetLinearSolver(mem, ls, jac);
  if (flag == KIN_SUCCESS) flag = KINSetJacFn(mem, jacobian);
  if (flag == KIN_SUCCESS) flag = KINSetMaxSetupCalls(mem, 1);  // exact Newton
  if (flag == KIN_SUCCESS) flag = KINSetFuncNormTol(mem, tolerance);
  if (flag == KIN_SUCCESS) flag = KINSetScaledStepTol(mem, 1e-300);  // stop on the residual only
  if (flag == KIN_SUCCESS) flag = KINSol(mem, u, KIN_NONE, scale, scale);
  result.ok = flag >= 0;
  if (!result.ok) result.message = KINGetReturnFlagName(flag);
  KINGetNumNonlinSolvIters(mem, &result.iterations);
  result.residual_evals = problem.residual_evals;
  result.d = problem.system.expand(view(u));
  KINFree(&mem);
  SUNLinSolFree(ls);
  SUNMatDestroy(jac);
  N_VDestroy(u);
  N_VDestroy(scale);
  SUNContext_Free(&sunctx);
  return result;
}

}  // namespace dda
