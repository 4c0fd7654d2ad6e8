#include "cms/reduced_body.hpp"

#include "core/so3.hpp"

namespace drillflex::cms {

Mat3 ReducedBody::NodeTranslationalMass(Index node) const {
  const double axial = node_mass[node];
  const double lateral = axial + node_lateral_mass[node];
  return Vec3(axial, lateral, lateral).asDiagonal();
}

MatX NodalReferenceMassMatrix(const ReducedBody& body) {
  const Index nf = body.flexible_count;
  MatX mass = MatX::Zero(6 + nf, 6 + nf);
  MatX translation(3, 6 + nf), rotation(3, 6 + nf);
  for (Index k = 0; k < body.node_count(); ++k) {
    // L_k at A = I, η = 0: translation [I, −ρ̃_k, Φ_k], rotation [0, I, Ψ_k].
    const Mat3 rho_skew = so3::Skew(body.node_positions[k]);
    translation << Mat3::Identity(), -rho_skew, body.node_translation_modes[k];
    rotation << Mat3::Zero(), Mat3::Identity(), body.node_rotation_modes[k];
    mass.noalias() += translation.transpose() * body.NodeTranslationalMass(k) * translation;
    mass.noalias() += rotation.transpose() * body.node_rotary_inertia[k] * rotation;
  }
  return mass;
}

MatX ReferenceMassMatrix(const ReducedBody& body) {
  const Index nf = body.flexible_count;
  MatX mass(6 + nf, 6 + nf);
  mass.topLeftCorner<6, 6>() = body.rigid_mass;
  mass.topRightCorner(6, nf) = body.rigid_flexible_mass;
  mass.bottomLeftCorner(nf, 6) = body.rigid_flexible_mass.transpose();
  mass.bottomRightCorner(nf, nf) = body.modal_mass;
  return mass;
}

}  // namespace drillflex::cms
