// Hole diameter along MD: piecewise constant or piecewise linear sections.
#pragma once

#include <cstddef>
#include <vector>

#include "well/survey.hpp"

namespace drillflex::well {

// Sections are listed top down. Section i spans (to_md[i-1], to_md[i]] (the first starts at
// MD 0, the last runs to the bottom); an MD on a boundary belongs to the section above it. A
// linear section (diameter_at_end set) varies from `diameter` at its start to `diameter_at_end`
// at its to_md; above MD 0 the first section's start value holds, below the last to_md its end
// value. The constructor throws LogicError for a non-positive or non-finite diameter, a missing
// or non-increasing to_md (to_md > 0), or a linear section without a to_md.
class HoleProfile {
 public:
  HoleProfile() = default;
  explicit HoleProfile(std::vector<HoleSection> sections);

  bool empty() const { return sections_.empty(); }
  // Hole diameter (m) at md; the last section runs to the bottom. LogicError when empty.
  double Diameter(double md) const;
  // Smallest diameter over [md_from, md_to] (m) (the order of the two bounds does not matter;
  // at a step the value just below a boundary counts as soon as the range extends past it).
  double MinDiameter(double md_from, double md_to) const;
  const std::vector<HoleSection>& sections() const { return sections_; }
  // The section holding md (a boundary MD belongs to the section above it). LogicError when empty.
  const HoleSection& SectionAt(double md) const { return sections_[SectionIndex(md)]; }

 private:
  std::size_t SectionIndex(double md) const;
  double SectionDiameter(std::size_t index, double md) const;

  std::vector<HoleSection> sections_;
  std::vector<double> starts_;  // start MD of each section (0 for the first)
};

}  // namespace drillflex::well
