// The model as a problem for the time integrator (solvers/generalized_alpha.hpp): the full
// residual R(t, q, v, a) = M(q) a + Q_v(q, v) + elastic forces + Σ elements at load factor 1 (every
// applied load at its full value) and its iteration matrix cK·K + cD·D + cM·M, in the model's fixed
// block pattern. The string's frames are quaternions, so Increment is the Lie-group update.
#pragma once

#include "model/system_model.hpp"
#include "solvers/problem.hpp"

namespace drillflex::model {

class DynamicModelProblem final : public solvers::Problem {
 public:
  explicit DynamicModelProblem(const SystemModel& model) : model_(model) {}

  Index num_positions() const override { return model_.num_positions(); }
  Index num_velocities() const override { return model_.num_velocities(); }
  VecX Increment(const VecX& q, const VecX& dv) const override { return model_.Increment(q, dv); }
  VecX Residual(double t, const VecX& q, const VecX& v, const VecX& a) const override {
    return model_.Residual(t, q, v, a, 1.0);
  }
  SparseMat IterationMatrix(double t, const VecX& q, const VecX& v, const VecX& a, double cK, double cD,
                            double cM) const override {
    return model_.IterationMatrix(t, q, v, a, 1.0, cK, cD, cM);
  }
  // Each body's coordinates turned by its spin (SystemModel::TurnCoordinates).
  void TransportCoordinates(const VecX& dv, VecX& x, bool inverse) const override {
    model_.TurnCoordinates(dv, x, inverse);
  }
  // The bodies, numbered along the string (each coupled only to its neighbours).
  std::vector<Eigen::Index> CoordinateBlocks() const override { return model_.BodyCoordinateBlocks(); }

 private:
  const SystemModel& model_;
};

}  // namespace drillflex::model
