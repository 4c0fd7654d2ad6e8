// The solver contract: the small interface through which every solver (static Newton, time
// integrator, eigen solvers on linearized systems) sees a problem. Solvers know nothing of drill
// strings; the model layer adapts a SystemModel + State to this interface.
//
// Equations of motion are written as a residual
//   R(t, q, v, a) = M(q) a + f_int(q, v) - f_ext(q, v, t),
// with q the positions (num_positions values, e.g. 4 per rotation stored as a unit quaternion)
// and v, a the velocities and accelerations (num_velocities values, in the tangent space of q).
// A position increment dv (same size as v) is applied with the Lie-group update q ⊕ dv.
#pragma once

#include <limits>
#include <string>
#include <vector>

#include "core/types.hpp"

namespace drillflex::solvers {

// A unilateral penalty term of a static problem's energy, ½ k ⟨δ(q)⟩² (⟨x⟩ = max(x, 0)): a wall
// contact's compliance, with δ its penetration. Linearized at a state: δ(q ⊕ p) ≈ value + gradient·p,
// the gradient sparse over v's coordinates.
struct PenaltyTerm {
  double value = 0.0;      // δ at the state (< 0: the gap), m
  double stiffness = 0.0;  // k, N/m
  std::vector<Index> indices;     // the coordinates of v the gradient covers
  std::vector<double> gradient;   // ∂δ/∂v there, one per index
};

class Problem {
 public:
  virtual ~Problem() = default;

  // Size of the position storage q (e.g. 7 per free rigid body: 3 translations + a quaternion).
  virtual Index num_positions() const = 0;
  // Size of v, a and of a position increment dv (e.g. 6 per free rigid body).
  virtual Index num_velocities() const = 0;

  // q ⊕ dv: applies the tangent-space increment dv to q (rotation-aware, e.g. so3::Compose for
  // quaternions; plain addition for Euclidean coordinates).
  virtual VecX Increment(const VecX& q, const VecX& dv) const = 0;

  // R(t, q, v, a) = M(q) a + f_int(q, v) - f_ext(q, v, t), in N (or N·m for rotational rows).
  // For statics v = a = 0. Must not return non-finite values for states the solver can reach;
  // the solvers check and stop with a SolverError if it does.
  virtual VecX Residual(double t, const VecX& q, const VecX& v, const VecX& a) const = 0;

  // cK·K + cD·D + cM·M, with K = ∂R/∂dv (the derivative along the increment q ⊕ dv, i.e. in the
  // tangent space), D = ∂R/∂v, M = ∂R/∂a. Size num_velocities × num_velocities.
  virtual SparseMat IterationMatrix(double t, const VecX& q, const VecX& v, const VecX& a,
                                    double cK, double cD, double cM) const = 0;
  // The same into `matrix`, which a problem may fill in place where it holds an earlier call's
  // pattern (no allocation of a large matrix a call). Default: replaced by IterationMatrix.
  virtual void IterationMatrixInto(SparseMat& matrix, double t, const VecX& q, const VecX& v, const VecX& a,
                                   double cK, double cD, double cM) const {
    matrix = IterationMatrix(t, q, v, a, cK, cD, cM);
  }

  // True when the iteration matrix may be reused between iterations and steps (it does not
  // depend, or barely depends, on the state: e.g. a linear problem). A hint, never a duty.
  virtual bool CanReuseIterationMatrix() const { return false; }

  // Blocks of v's coordinates (the first of each, ascending from 0, then num_velocities) such that
  // the iteration matrix couples every block only with the one before and the one after it (a
  // string's bodies, joined to their neighbours): a hint for a block-tridiagonal factorization,
  // which the solver checks against the matrix's pattern. Empty: none.
  virtual std::vector<Eigen::Index> CoordinateBlocks() const { return {}; }

  // For solving with an iteration matrix factorized at an earlier state: x ← P x (inverse: Pᵀ x),
  // P orthogonal, taking v's coordinates at the present state to those of the earlier one, `dv`
  // the sum of the increments between them, such that the present matrix is ≈ Pᵀ S P. A model
  // whose bodies spin about their axes turns their body-frame coordinates with them (a matrix
  // factorized 0.04 rad of spin earlier is otherwise off by the stiff couplings turned with the
  // frames). Default: P = I.
  virtual void TransportCoordinates(const VecX& /*dv*/, VecX& /*x*/, bool /*inverse*/) const {}
};

// A problem for the static Newton solver: a load factor λ in [0, 1] scales the applied loads
// (the problem decides what it scales), and a force scale sets the residual tolerance.
class StaticProblem : public Problem {
 public:
  // Sets λ for the following Residual / IterationMatrix calls. Default: no load stepping.
  virtual void SetLoadFactor(double /*load_factor*/) {}

  // A typical force (N) of the problem at full load (e.g. the weight of the string); the
  // residual tolerance is relative to it. 0 = unknown: the solver then uses |R| of the start
  // state at full load.
  virtual double ForceScale() const { return 0.0; }

  // The length of an increment dv at q for the trust radius NewtonOptions::max_increment.
  // Default |dv|∞; a model may measure what matters to it (e.g. how far a node moves).
  virtual double StepLength(const VecX& /*q*/, const VecX& dv) const { return dv.lpNorm<Eigen::Infinity>(); }

  // The increment dv (≥ 0 each) of one rounding unit of the stored state at q: how finely q can
  // say where the system is (a position 3 km from the origin only to ~4.5e-13 m). The solver
  // measures with it the round-off floor of the residual (SolveStatic). Empty: not known, no floor.
  virtual VecX StateResolution(const VecX& /*q*/) const { return {}; }

  // Where coordinate `index` of v (or a residual row) sits in the problem, for messages: e.g. the
  // body and its distance from the bit. Default: the index alone.
  virtual std::string DescribeCoordinate(Index index) const { return "coordinate " + std::to_string(index); }

  // Π(to) − Π(from), J: the change of the total potential energy between two states at the present
  // load factor, for a problem whose residual (v = a = 0) is the gradient of Π along Increment
  // (conservative loads; a dead moment by its work over the turn between the two states). Formed
  // as a sum of differences, term by term, so that a small change of a large energy is not lost to
  // round-off. NaN: the problem has no energy (solvers/energy_trust_region.hpp cannot be used).
  virtual double EnergyChange(const VecX& /*from*/, const VecX& /*to*/) const {
    return std::numeric_limits<double>::quiet_NaN();
  }

  // The unilateral penalty terms of Π at q (every one, touching or not; those with δ > 0 are in the
  // residual and the tangent), so that an energy solver can model contacts that a step closes or
  // opens (solvers/energy_trust_region.hpp). Empty: none, or not known.
  virtual std::vector<PenaltyTerm> PenaltyTerms(const VecX& /*q*/) const { return {}; }
};

// The residual's round-off floor at q and the problem's load factor: how much |R| changes when every coordinate
// moves by one rounding unit (StaticProblem::StateResolution) with signs from a fixed pseudo-random
// pattern; 0 when the problem does not say. No state can bring |R| below it.
double ResidualRoundoffFloor(StaticProblem& problem, const VecX& q, double time = 0.0);

// cK·K + cD·D + cM·M of `problem` by central differences of its residual: the position
// perturbations go through Increment (q ⊕ ±h e_j), those of v and a are h·max(1, |x_j|).
// Only the parts with a non-zero coefficient are evaluated (2·n residual calls each). Used by
// tests everywhere to check analytic Jacobians. Error O(h²) plus round-off O(ε|R|/h).
SparseMat FiniteDifferenceIterationMatrix(const Problem& problem, double t, const VecX& q,
                                          const VecX& v, const VecX& a, double cK, double cD,
                                          double cM, double h = 1e-6);

// ‖A − B‖_F / max(‖A‖_F, ‖B‖_F); 0 when both are zero. Throws LogicError on a size mismatch.
double RelativeMatrixError(const SparseMat& a, const SparseMat& b);
double RelativeMatrixError(const MatX& a, const MatX& b);

}  // namespace drillflex::solvers
