// The whole multibody model of a string: immutable once built (model/builder.hpp). It owns the
// bodies and force elements and assembles the residual R(t, q, v, a; λ) = M a + Q_v + f_elastic +
// Σ elements, its iteration matrix cK·K + cD·D + cM·M (sparse, block-banded) and the energies.
// The changing state (q, v) lives outside, in plain vectors.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "model/block_pattern.hpp"
#include "model/body.hpp"
#include "model/element_handle.hpp"
#include "model/force_element.hpp"
#include "solvers/problem.hpp"

namespace drillflex::model {

struct Energies {
  double kinetic = 0.0;
  double elastic = 0.0;    // bodies' strain energy
  double potential = 0.0;  // force elements (springs, loads)
  double total() const { return kinetic + elastic + potential; }
};

class SystemModel {
 public:
  SystemModel(std::vector<Body> bodies, std::vector<std::unique_ptr<ForceElement>> elements, double length);
  SystemModel(SystemModel&&) = default;
  SystemModel& operator=(SystemModel&&) = default;

  const std::vector<Body>& bodies() const { return bodies_; }
  const std::vector<std::unique_ptr<ForceElement>>& elements() const { return elements_; }
  // The element a handle names, with its type (the builder made it so: model/element_handle.hpp).
  template <class E>
  const E& Get(ElementHandle<E> handle) const {
    return static_cast<const E&>(*elements_[handle.index()]);
  }
  Index num_positions() const { return num_positions_; }
  Index num_velocities() const { return num_velocities_; }
  double length() const { return length_; }  // of the string, m

  VecX ReferencePositions() const;
  // The first velocity coordinate of each body, then num_velocities(): the blocks of a
  // block-tridiagonal factorization (each body is coupled only to its neighbours along the string).
  std::vector<Eigen::Index> BodyCoordinateBlocks() const;
  VecX Increment(const VecX& q, const VecX& dv) const;
  // The same to first order (the same derivative at dv = 0, so the same tangent matrices), but a
  // body's turn φ about its own axis (the x part of its frame rotation δθ) moves none of its points:
  // the frame is tilted by the rest of δθ first and then turned about its new axis,
  // A ← A exp(δθ_⊥) Rx(φ), and the modes keep the shape they held, η ← G(−φ)(η + φ J η + δη)
  // (cms::ReducedBody::twist_generator). Plain Increment turns the bending with the frame (an
  // error of ½φ²|J²η|) and tilts about an axis turned by ~φ/2, errors the stiff couplings amplify:
  // a long rotating string twists by radians (V7's 10,000 ft pipe: 21 rad at the bit), and Newton's
  // steps of tenths of a radian there then failed. For the static solver; the time integrator
  // keeps Increment.
  VecX IncrementKeepingShape(const VecX& q, const VecX& dv) const;
  // x ← P x (inverse: Pᵀ x) with P = diag over the bodies of (I, Rx(φ_b), G(φ_b)), φ_b = dv's x
  // part of body b's frame rotation: a vector of v's coordinates at a state whose bodies have since
  // turned by φ_b about their axes (their shapes kept) written in the coordinates of the earlier
  // state. P is orthogonal (G(φ)ᵀ = G(−φ)), and for axisymmetric bodies whose modes are closed
  // under the turn the iteration matrix after the turn is Pᵀ S P of the one before it. Turns below
  // 1e-6 rad are taken as 0.
  void TurnCoordinates(const VecX& dv, VecX& x, bool inverse) const;
  // One rounding unit of each coordinate of q, as an increment (solvers::StaticProblem::
  // StateResolution): ε·max(|Δr|∞, L) for a frame's displacement (added to node offsets up to the
  // body length L), ε for its rotation (a unit quaternion's
  // components), ε·|η_j| for a modal coordinate (ε = 2⁻⁵²).
  VecX StateResolution(const VecX& q) const;
  std::vector<BodyPose> Poses(const VecX& q) const;
  // The largest lateral translation of any node for the increment dv at q, to first order: the
  // part of δr + A (δθ × u_k + Φ_k δη) across the body axis A e_x (m). A twist about the axis
  // moves no node on it; axial motion (the stretch of a long string) closes no wall contact.
  double LargestLateralNodeTranslation(const VecX& q, const VecX& dv) const;

  VecX Residual(double t, const VecX& q, const VecX& v, const VecX& a, LoadParameters load) const;
  // Both matrices have a fixed pattern (model/block_pattern.hpp): dense body blocks and the blocks of
  // bodies sharing an element, structural zeros included, the same at every state.
  SparseMat IterationMatrix(double t, const VecX& q, const VecX& v, const VecX& a, LoadParameters load, double cK,
                            double cD, double cM) const;
  // The same into `matrix`: where it holds this model's pattern already (a matrix from an earlier
  // call: the same size, entries and column starts), only its values are written, with no
  // allocation or copy of the ~1e6-entry pattern; else it is replaced.
  void IterationMatrixInto(SparseMat& matrix, double t, const VecX& q, const VecX& v, const VecX& a,
                           LoadParameters load, double cK, double cD, double cM) const;
  // The bodies' mass, with the fluid lumps a transient's bodies carry (model/fluid_inertia.hpp).
  SparseMat MassMatrix(const VecX& q) const;
  // Kinetic energy: the bodies' and their fluid lumps'.
  Energies ComputeEnergies(const VecX& q, const VecX& v, LoadParameters load) const;
  // Π(to) − Π(from) at rest (J): the bodies' elastic energies and the elements' potential energies
  // (with the dead loads' work over the step, ForceElement::PotentialEnergyChange), each term's
  // difference formed on its own before the sum, so that a small change of a large energy survives
  // round-off. The static residual at `load` is its gradient along Increment.
  double PotentialEnergyChange(const VecX& from, const VecX& to, LoadParameters load) const;
  // The elements' unilateral penalties at q (ForceElement::Penalty), their gradients over v.
  std::vector<solvers::PenaltyTerm> PenaltyTerms(const VecX& q, LoadParameters load) const;

  // The element's state at (q, v): its bodies' poses and velocities.
  ElementState StateOf(const ForceElement& element, const std::vector<BodyPose>& poses, const VecX& v,
                       double t, LoadParameters load) const;
  // The same into `state`, reusing its storage.
  void FillState(const ForceElement& element, const std::vector<BodyPose>& poses, const VecX& v, double t,
                 LoadParameters load, ElementState& state) const;
  Index IndexOf(const Body* body) const;
  // Where velocity coordinate `index` sits, for messages: its body, the body's span from the bit
  // and the coordinate's kind (frame translation or rotation, or mode j).
  std::string DescribeCoordinate(Index index) const;

  // The body and node at a distance s from the bit (the nearest node; at a joint, the upper body).
  std::pair<Index, Index> NodeAt(double s) const;
  // The force scale of the model's applied loads (N), for solver tolerances.
  double force_scale() const { return force_scale_; }
  void set_force_scale(double scale) { force_scale_ = scale; }

 private:
  std::vector<Body> bodies_;
  std::vector<std::unique_ptr<ForceElement>> elements_;
  Index num_positions_ = 0;
  Index num_velocities_ = 0;
  double length_ = 0.0;
  double force_scale_ = 1.0;
  std::vector<std::vector<Index>> element_bodies_;  // body indices of each element
  std::vector<std::vector<Index>> body_elements_;   // per body: the elements touching it, ascending
  std::vector<Index> shared_elements_;              // the elements touching more than one body
  // The first row of body `body` in element `element`'s local vector.
  Index LocalOffset(Index element, Index body) const;
  BlockPattern iteration_pattern_;  // body blocks and the blocks of bodies sharing an element
  BlockPattern mass_pattern_;       // body blocks only
};

// NodeAt over a list of bodies (used while building).
std::pair<Index, Index> FindNodeAt(const std::vector<Body>& bodies, double s);

}  // namespace drillflex::model
