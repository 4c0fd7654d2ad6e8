// The two choices of a body's finite-element model that a case makes (model.mass, model.beam): the
// element mass matrix and the beam theory. Here alone, so that the model's settings name them without
// the element code.
#pragma once

namespace drillflex::fe {

enum class BeamTheory { kEulerBernoulli, kTimoshenko };
enum class MassKind { kConsistent, kLumped };

}  // namespace drillflex::fe
