// The model as a problem for the static Newton solver (solvers/newton.hpp): v = a = 0, the model
// evaluated under a parameter block (model/load_parameters.hpp: the loads, the friction, the
// sliding, the supports' stiffness) whose load factor (or friction factor) the solver's load
// factor λ multiplies: its load stepping from 0 to 1 ramps the loads to the block's (e.g.
// load_factor = μ: μ times the case's, the buckling analysis).
#pragma once

#include <cmath>

#include "model/system_model.hpp"
#include "solvers/problem.hpp"

namespace drillflex::model {

class StaticModelProblem : public solvers::StaticProblem {
 public:
  // What the solver's load factor λ (SetLoadFactor) ramps: the applied loads (the block's load
  // factor × λ), or, with the loads at the block's, the wall friction (its friction factor × λ: the
  // string from at rest to moving, static-solver.md §6).
  enum class Ramp { kLoads, kFriction };

  explicit StaticModelProblem(const SystemModel& model, const LoadParameters& parameters = 1.0,
                              Ramp ramp = Ramp::kLoads)
      : model_(model), base_(parameters), load_(parameters), ramp_(ramp) {}

  Index num_positions() const override { return model_.num_positions(); }
  Index num_velocities() const override { return model_.num_velocities(); }
  // Twists keep the bodies' shapes (SystemModel::IncrementKeepingShape).
  VecX Increment(const VecX& q, const VecX& dv) const override { return model_.IncrementKeepingShape(q, dv); }
  VecX Residual(double t, const VecX& q, const VecX& v, const VecX& a) const override {
    return model_.Residual(t, q, v, a, Load());
  }
  SparseMat IterationMatrix(double t, const VecX& q, const VecX& v, const VecX& a, double cK, double cD,
                            double cM) const override {
    return model_.IterationMatrix(t, q, v, a, Load(), cK, cD, cM);
  }
  void IterationMatrixInto(SparseMat& matrix, double t, const VecX& q, const VecX& v, const VecX& a, double cK,
                           double cD, double cM) const override {
    model_.IterationMatrixInto(matrix, t, q, v, a, Load(), cK, cD, cM);
  }
  void SetLoadFactor(double load_factor) override {
    if (ramp_ == Ramp::kLoads) {
      load_.load_factor = base_.load_factor * load_factor;
    } else {
      load_.friction_factor = base_.friction_factor * load_factor;
    }
  }
  double ForceScale() const override { return std::abs(base_.load_factor) * model_.force_scale(); }
  // How far the increment moves the farthest node across the string (m): the trust radius then
  // limits how fast contacts close, and leaves the twist and the axial stretch free.
  double StepLength(const VecX& q, const VecX& dv) const override {
    return model_.LargestLateralNodeTranslation(q, dv);
  }
  VecX StateResolution(const VecX& q) const override { return model_.StateResolution(q); }
  std::string DescribeCoordinate(Index index) const override { return model_.DescribeCoordinate(index); }
  double EnergyChange(const VecX& from, const VecX& to) const override {
    return model_.PotentialEnergyChange(from, to, Load());
  }
  std::vector<solvers::PenaltyTerm> PenaltyTerms(const VecX& q) const override {
    return model_.PenaltyTerms(q, Load());
  }
  // The bodies, numbered along the string (each coupled only to its neighbours).
  std::vector<Eigen::Index> CoordinateBlocks() const override { return model_.BodyCoordinateBlocks(); }
  double load_factor() const { return load_.load_factor; }

 private:
  const LoadParameters& Load() const { return load_; }

  const SystemModel& model_;
  LoadParameters base_;  // at λ = 1
  LoadParameters load_;  // at the present λ
  Ramp ramp_ = Ramp::kLoads;
};

}  // namespace drillflex::model
