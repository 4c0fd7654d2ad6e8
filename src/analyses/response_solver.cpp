#include "analyses/response_solver.hpp"

#include "analyses/linearization.hpp"
#include "fe/annulus_fluid.hpp"

namespace drillflex::analyses {
namespace {

// The structural damping ratio ζ_s of the case (model.structural_damping, the same on every body).
double StructuralDampingRatio(const model::SystemModel& model) {
  return model.bodies().empty() ? 0.0 : model.bodies().front().reduced->structural_damping;
}

}  // namespace

SweepSystem AssembleSweepSystem(const model::SystemModel& model, const model::LateralFluid& fluid, const VecX& q) {
  SweepSystem sweep;
  sweep.loss_factor = 2.0 * StructuralDampingRatio(model);
  const LinearizedSystem linear = Linearize(model, q, 1.0);
  sweep.system = {linear.mass, linear.damping, SparseMat(), linear.stiffness};
  if (!fluid.empty()) {
    sweep.system.mass += model::ComputeLateralFluidMatrices(model, fluid, q, 0.0, model::FluidPart::Internal).mass;
    for (model::AnnulusGroup& group : model::ComputeAnnulusGroups(model, fluid, q)) {
      sweep.annulus_radii.emplace_back(group.rod_radius, group.hole_radius);
      sweep.terms.push_back(std::move(group.unit_mass));
    }
    if (!sweep.annulus_radii.empty()) sweep.fluid = &fluid;
  }
  sweep.terms.push_back(linear.stiffness);  // the hysteretic term, last
  for (const model::Body& body : model.bodies()) sweep.options.block_starts.push_back(body.v_offset);
  sweep.options.block_starts.push_back(model.num_velocities());
  return sweep;
}

std::vector<solvers::FrequencyTermCoefficients> SweepTermCoefficients(const SweepSystem& sweep, double frequency) {
  std::vector<solvers::FrequencyTermCoefficients> coefficients;
  for (const auto& [rod_radius, hole_radius] : sweep.annulus_radii) {
    fe::AnnulusFluidCoefficients c;
    if (sweep.fluid->added_mass_override >= 0.0) {
      c.added_mass = sweep.fluid->added_mass_override;
    } else {
      const bool viscous = sweep.fluid->frequency_dependent() && frequency > 0.0;
      c = fe::ComputeAnnulusFluidCoefficients(rod_radius, hole_radius, viscous ? frequency : 0.0,
                                           viscous ? sweep.fluid->kinematic_viscosity : 0.0);
    }
    // m_a = C_m U_g, c_a = C_v ω U_g (model/lateral_fluid.hpp).
    coefficients.push_back({c.added_mass, c.damping * frequency});
  }
  coefficients.push_back({0.0, frequency > 0.0 ? sweep.loss_factor / frequency : 0.0});
  return coefficients;
}

SparseMat ReferenceMass(const SweepSystem& sweep, double reference_frequency) {
  SparseMat mass = sweep.system.mass;
  const std::vector<solvers::FrequencyTermCoefficients> coefficients = SweepTermCoefficients(sweep, reference_frequency);
  for (Index g = 0; g < std::ssize(sweep.annulus_radii); ++g) mass += coefficients[g].mass * sweep.terms[g];
  return mass;
}

ResponseSolver::ResponseSolver(std::shared_ptr<const SweepSystem> sweep)
    : sweep_(std::move(sweep)), direct_(std::make_unique<solvers::HarmonicSolver>(sweep_->system, sweep_->terms, sweep_->options)) {}

ResponseSolver::ResponseSolver(std::shared_ptr<const SweepSystem> sweep,
                               std::shared_ptr<const solvers::ProjectedHarmonicSolver> modal)
    : sweep_(std::move(sweep)), modal_(std::move(modal)) {}

solvers::ComplexMat ResponseSolver::Solve(double frequency, const solvers::ComplexMat& loads) {
  const std::vector<solvers::FrequencyTermCoefficients> coefficients = SweepTermCoefficients(*sweep_, frequency);
  if (modal_) return modal_->Solve(frequency, loads, 0.0, coefficients);
  return direct_->Solve(frequency, loads, 0.0, coefficients);
}

}  // namespace drillflex::analyses
