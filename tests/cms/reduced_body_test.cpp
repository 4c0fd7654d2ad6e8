#include "cms/reduced_body.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "cms/craig_bampton.hpp"
#include "fe/body_fe_model.hpp"

namespace drillflex::cms {
namespace reduced_body_test {

// A 9 m drill-pipe body (5 in × 4.276 in) with internal mud and annulus added mass.
fe::BodySpec PipeBody(fe::MassKind mass) {
  fe::BodySpec spec;
  spec.section = {0.127, 0.1086104};
  spec.material = {"steel", 2.1e11, 0.3, 7850.0};
  spec.length = 9.0;
  spec.element_count = 10;
  spec.options.mass = mass;
  spec.options.internal_fluid_mass_per_length = 1198.0 * spec.section.bore_area();
  spec.options.added_lateral_mass_per_length = 1.6 * 1198.0 * spec.section.outer_area();
  return spec;
}

double Rel(double value, double reference) {
  return std::abs(value - reference) / std::abs(reference);
}

TEST(ReducedBody, NodeSumIsExactForLumpedMass) {
  const ReducedBody body = Reduce(fe::BuildBodyFeModel(PipeBody(fe::MassKind::kLumped)), 12, 0.0);
  const MatX nodal = NodalReferenceMassMatrix(body);
  const MatX reference = ReferenceMassMatrix(body);
  EXPECT_LT((nodal - reference).norm(), 1e-12 * reference.norm());
  // Tisserand: the lumped node sum has no rigid–flexible coupling either.
  EXPECT_LT(nodal.topRightCorner(6, body.flexible_count).norm(),
            1e-10 * std::sqrt(reference.norm()));
}

TEST(ReducedBody, ConsistentReferenceMassHasTheContinuumRigidInertia) {
  const fe::BodySpec spec = PipeBody(fe::MassKind::kConsistent);
  const ReducedBody body = Reduce(fe::BuildBodyFeModel(spec), 12, 0.0);
  const double l = spec.length;
  const double structural = spec.material.density * spec.section.area() * l;
  const double lateral = structural + spec.options.lateral_mass_per_length() * l;
  const double rho_i_l = spec.material.density * spec.section.second_moment() * l;
  // Translation: diag(m, m + m_fluid, m + m_fluid); the fluid moves laterally only.
  EXPECT_LT(Rel(body.rigid_mass(0, 0), structural), 1e-13);
  EXPECT_LT(Rel(body.rigid_mass(1, 1), lateral), 1e-13);
  EXPECT_LT(Rel(body.rigid_mass(2, 2), lateral), 1e-13);
  // Rotation about z through the origin (node 0): ∫ μ x² dx + ρIL = μL³/3 + ρIL.
  EXPECT_LT(Rel(body.rigid_mass(5, 5), lateral * l * l / 3 + rho_i_l), 1e-12);
  EXPECT_LT(Rel(body.rigid_mass(1, 5), lateral * l / 2), 1e-12);
  EXPECT_LT(Rel(body.rigid_mass(3, 3), spec.material.density * spec.section.polar_moment() * l),
            1e-12);
  // The structural body alone: mass, centre, inertia about the centre.
  EXPECT_LT(Rel(body.total_mass, structural), 1e-14);
  EXPECT_DOUBLE_EQ(body.center_of_mass.x(), 4.5);
  EXPECT_LT(Rel(body.inertia_about_center(1, 1), rho_i_l + structural * l * l / 12), 1e-14);
  // The node sum of the lumped data differs from the consistent reference (it is not exact): the
  // translational mass agrees, the rotational inertia about the origin does not.
  const MatX nodal = NodalReferenceMassMatrix(body);
  EXPECT_LT(Rel(nodal(1, 1), lateral), 1e-13);
  EXPECT_GT(Rel(nodal(5, 5), body.rigid_mass(5, 5)), 1e-4);
  // Node translational mass: isotropic structural part plus lateral fluid.
  const Mat3 m5 = body.NodeTranslationalMass(5);
  EXPECT_LT(Rel(m5(0, 0), structural / 10), 1e-13);
  EXPECT_LT(Rel(m5(2, 2), lateral / 10), 1e-13);
  EXPECT_EQ(m5(0, 1), 0.0);
}

TEST(ReducedBody, NodeRowsAreTheRowsOfU) {
  const ReducedBody body =
      Reduce(fe::BuildBodyFeModel(PipeBody(fe::MassKind::kConsistent)), 6, 0.0);
  ASSERT_EQ(body.node_count(), 11);
  for (int k = 0; k < body.node_count(); ++k) {
    EXPECT_EQ(body.node_translation_modes[k], body.mode_shapes.middleRows(6 * k, 3));
    EXPECT_EQ(body.node_rotation_modes[k], body.mode_shapes.middleRows(6 * k + 3, 3));
    EXPECT_DOUBLE_EQ(body.node_positions[k].x(), 0.9 * k);
  }
}

}  // namespace reduced_body_test
}  // namespace drillflex::cms
