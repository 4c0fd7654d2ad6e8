// One force element of a model as a solvers::Problem, and spun, bent, moving states, for checking
// an element's analytic stiffness and damping against central differences of its own residual.
#pragma once

#include <random>

#include "model/system_model.hpp"
#include "solvers/problem.hpp"

namespace drillflex::model::testing {

// One element of a model as a problem: its residual and matrices over the whole velocity vector.
class ElementProblem : public solvers::Problem {
 public:
  ElementProblem(const SystemModel& model, int element) : model_(model), element_(*model.elements()[element]) {}
  template <class E>
  ElementProblem(const SystemModel& model, ElementHandle<E> element) : ElementProblem(model, element.index()) {}
  Index num_positions() const override { return model_.num_positions(); }
  Index num_velocities() const override { return model_.num_velocities(); }
  VecX Increment(const VecX& q, const VecX& dv) const override { return model_.Increment(q, dv); }
  VecX Residual(double t, const VecX& q, const VecX& v, const VecX&) const override {
    ElementContribution c;
    element_.Evaluate(State(t, q, v), false, c);
    VecX residual = VecX::Zero(num_velocities());
    residual.segment(Body().v_offset, Body().velocity_count()) = c.force;
    return residual;
  }
  SparseMat IterationMatrix(double t, const VecX& q, const VecX& v, const VecX&, double cK, double cD,
                            double) const override {
    ElementContribution c;
    element_.Evaluate(State(t, q, v), true, c);
    MatX dense = MatX::Zero(num_velocities(), num_velocities());
    const int o = Body().v_offset, n = Body().velocity_count();
    dense.block(o, o, n, n) = cK * c.stiffness + cD * c.damping;
    return dense.sparseView();
  }
  ElementState State(double t, const VecX& q, const VecX& v) const {
    poses_ = model_.Poses(q);
    return model_.StateOf(element_, poses_, v, t, 1.0);
  }

 private:
  const model::Body& Body() const { return *element_.bodies()[0]; }
  const SystemModel& model_;
  const ForceElement& element_;
  mutable std::vector<BodyPose> poses_;
};

struct Errors {
  double stiffness, damping;
};

inline Errors JacobianErrors(const ElementProblem& problem, double t, const VecX& q, const VecX& v) {
  const VecX a = VecX::Zero(v.size());
  return {solvers::RelativeMatrixError(MatX(problem.IterationMatrix(t, q, v, a, 1.0, 0.0, 0.0)),
                                       MatX(solvers::FiniteDifferenceIterationMatrix(problem, t, q, v, a, 1.0, 0.0, 0.0))),
          solvers::RelativeMatrixError(MatX(problem.IterationMatrix(t, q, v, a, 0.0, 1.0, 0.0)),
                                       MatX(solvers::FiniteDifferenceIterationMatrix(problem, t, q, v, a, 0.0, 1.0, 0.0)))};
}

// Every body turned about the string axis (x) by `spin` (rad), then perturbed at random (bending
// rotations and translations of `size`, modal coordinates 1e-3 of it).
inline VecX SpunPositions(const SystemModel& model, double spin, double size, std::mt19937& rng) {
  VecX dv = VecX::Zero(model.num_velocities());
  for (const Body& body : model.bodies()) dv[body.v_offset + 3] = spin;
  const VecX spun = model.Increment(model.ReferencePositions(), dv);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i = 0; i < dv.size(); ++i) dv[i] = size * u(rng);
  for (const Body& body : model.bodies()) dv.segment(body.v_offset + 6, body.flexible_count) *= 1e-3;
  return model.Increment(spun, dv);
}

// Random velocities of `size` about a spin at `rate` (rad/s about x).
inline VecX SpinningVelocities(const SystemModel& model, double rate, double size, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  VecX v(model.num_velocities());
  for (int i = 0; i < v.size(); ++i) v[i] = size * u(rng);
  for (const Body& body : model.bodies()) v[body.v_offset + 3] += rate;
  return v;
}

}  // namespace drillflex::model::testing
