// The model as a problem for the static Newton solver (solvers/newton.hpp): v = a = 0, the load
// factor scales every applied load (gravity, point and distributed loads, WOB). With a
// `load_scale`, the model's loads are load_scale × the solver's load factor, so that the solver's
// load stepping from 0 to 1 ramps the loads to load_scale times the case's (buckling analysis).
#pragma once

#include <cmath>

#include "model/system_model.hpp"
#include "solvers/problem.hpp"

namespace drillflex::model {

class StaticModelProblem : public solvers::StaticProblem {
 public:
  // What the solver's load factor λ (SetLoadFactor) ramps: the applied loads (load_scale × λ), or,
  // with the loads at load_scale, the wall friction coefficients (friction factor λ: the string
  // from at rest to rotating, static-solver.md §6).
  enum class Ramp { kLoads, kFriction };

  explicit StaticModelProblem(const SystemModel& model, double load_scale = 1.0, Ramp ramp = Ramp::kLoads)
      : model_(model), load_scale_(load_scale), load_factor_(load_scale), ramp_(ramp) {}

  int num_positions() const override { return model_.num_positions(); }
  int num_velocities() const override { return model_.num_velocities(); }
  // Twists keep the bodies' shapes (SystemModel::IncrementKeepingShape).
  VecX Increment(const VecX& q, const VecX& dv) const override { return model_.IncrementKeepingShape(q, dv); }
  VecX Residual(double t, const VecX& q, const VecX& v, const VecX& a) const override {
    return model_.Residual(t, q, v, a, Load());
  }
  SparseMat IterationMatrix(double t, const VecX& q, const VecX& v, const VecX& a, double cK, double cD,
                            double cM) const override {
    return model_.IterationMatrix(t, q, v, a, Load(), cK, cD, cM);
  }
  void SetLoadFactor(double load_factor) override {
    if (ramp_ == Ramp::kLoads) {
      load_factor_ = load_scale_ * load_factor;
    } else {
      friction_factor_ = load_factor;
    }
  }
  double ForceScale() const override { return std::abs(load_scale_) * model_.force_scale(); }
  bool IsIterationMatrixSymmetric() const override { return false; }
  // How far the increment moves the farthest node across the string (m): the trust radius then
  // limits how fast contacts close, and leaves the twist and the axial stretch free.
  double StepLength(const VecX& q, const VecX& dv) const override {
    return model_.LargestLateralNodeTranslation(q, dv);
  }
  VecX StateResolution(const VecX& q) const override { return model_.StateResolution(q); }
  std::string DescribeCoordinate(int index) const override { return model_.DescribeCoordinate(index); }
  double EnergyChange(const VecX& from, const VecX& to) const override {
    return model_.PotentialEnergyChange(from, to, Load());
  }
  std::vector<solvers::PenaltyTerm> PenaltyTerms(const VecX& q) const override {
    return model_.PenaltyTerms(q, Load());
  }
  double load_factor() const { return load_factor_; }

 private:
  LoadParameters Load() const { return {load_factor_, friction_factor_}; }

  const SystemModel& model_;
  double load_scale_ = 1.0;
  double load_factor_ = 1.0;  // the model's load factor: load_scale × the solver's (Ramp::kLoads)
  double friction_factor_ = 1.0;  // the solver's load factor with Ramp::kFriction
  Ramp ramp_ = Ramp::kLoads;
};

}  // namespace drillflex::model
