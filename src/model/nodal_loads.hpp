// Applied dead loads on one body: a force and a moment at each node, fixed in the global frame and
// scaled by the load factor. Gravity (buoyed weight), distributed loads (as work-equivalent nodal
// forces and moments) and point loads of a body are all gathered into one element per body.
// Generalized force of a nodal force F and moment M (method.md §4, Q_e = Σ L_kᵀ (F_k, M_k)):
//   [F;  u_k × AᵀF + AᵀM;  Φ_kᵀ AᵀF + Ψ_kᵀ AᵀM].
#pragma once

#include <vector>

#include "model/force_element.hpp"

namespace drillflex::model {

class NodalLoadElement : public ForceElement {
 public:
  NodalLoadElement(const Body* body, std::vector<Vec3> forces, std::vector<Vec3> moments);
  std::string Describe() const override;
  const std::vector<Vec3>& forces() const { return forces_; }

 protected:
  void DoEvaluate(const ElementState& state, bool with_matrices, ElementContribution& out) const override;
  // −λ Σ F_k · (r_k − r_k,ref) is path-dependent for the moments; only the forces' part is reported.
  double DoPotentialEnergy(const ElementState& state) const override;

 private:
  std::vector<Vec3> forces_;   // N, global, per node
  std::vector<Vec3> moments_;  // N·m, global, per node
};

// Work-equivalent nodal forces and moments of a uniform line load q (N/m, global) on a straight
// element from `start` to `end` (global positions): q h/2 at each end and ±(h²/12) t × q
// (t the unit axis): the fixed-end actions of a uniformly loaded beam.
void AddUniformLineLoad(const Vec3& start, const Vec3& end, const Vec3& load_per_length, Vec3& force_start,
                        Vec3& moment_start, Vec3& force_end, Vec3& moment_end);

}  // namespace drillflex::model
