// Hole diameter along MD: piecewise constant or piecewise linear sections.
#pragma once

#include <vector>

#include "well/survey.hpp"

namespace drillflex::well {

class HoleProfile {
 public:
  HoleProfile() = default;
  explicit HoleProfile(std::vector<HoleSection> sections);

  bool empty() const { return sections_.empty(); }
  // Hole diameter (m) at md; the last section runs to the bottom.
  double Diameter(double md) const;
  // Smallest diameter over [md_from, md_to] (m).
  double MinDiameter(double md_from, double md_to) const;
  const std::vector<HoleSection>& sections() const { return sections_; }

 private:
  std::vector<HoleSection> sections_;
};

}  // namespace drillflex::well
