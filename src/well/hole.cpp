// Hole diameter along MD: sections listed top down, constant or linear within each.
#include "well/hole.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "core/error.hpp"

namespace drillflex::well {
namespace {

void Fail(std::size_t index, const char* what) {
  std::string message = "HoleProfile: section ";
  message.append(std::to_string(index + 1)).append(": ").append(what);
  throw LogicError(message);
}

bool PositiveFinite(double value) { return std::isfinite(value) && value > 0.0; }

}  // namespace

HoleProfile::HoleProfile(std::vector<HoleSection> sections) : sections_(std::move(sections)) {
  double previous_to = 0.0;
  for (std::size_t i = 0; i < sections_.size(); ++i) {
    const HoleSection& section = sections_[i];
    const bool last = i + 1 == sections_.size();
    if (!PositiveFinite(section.diameter)) Fail(i, "the diameter must be positive and finite");
    if (section.diameter_at_end && !PositiveFinite(*section.diameter_at_end)) {
      Fail(i, "the diameter at the end must be positive and finite");
    }
    if (!section.to_md && !last) Fail(i, "only the last section may omit to_md");
    if (!section.to_md && section.diameter_at_end) {
      Fail(i, "a linear section (diameter_at_end) needs a to_md");
    }
    for (const auto& mu : {section.friction, section.axial_friction}) {
      if (mu && !(std::isfinite(*mu) && *mu >= 0.0)) Fail(i, "a friction coefficient must be finite and >= 0");
    }
    if (section.to_md && !(std::isfinite(*section.to_md) && *section.to_md > previous_to)) {
      Fail(i, "to_md must be finite and increase down the list (the first section starts at MD 0)");
    }
    starts_.push_back(previous_to);
    if (section.to_md) previous_to = *section.to_md;
  }
}

std::size_t HoleProfile::SectionIndex(double md) const {
  if (sections_.empty()) throw LogicError("HoleProfile: no hole sections");
  // The first section whose to_md is at or below md; every section but the last has a to_md.
  const auto last = sections_.end() - 1;
  const auto found = std::lower_bound(sections_.begin(), last, md,
                                      [](const HoleSection& s, double value) { return *s.to_md < value; });
  return static_cast<std::size_t>(found - sections_.begin());
}

double HoleProfile::SectionDiameter(std::size_t index, double md) const {
  const HoleSection& section = sections_[index];
  if (!section.diameter_at_end) return section.diameter;
  // Linear from the section start to its to_md, held constant outside.
  const double start = starts_[index];
  const double fraction = std::clamp((md - start) / (*section.to_md - start), 0.0, 1.0);
  return section.diameter + fraction * (*section.diameter_at_end - section.diameter);
}

double HoleProfile::Diameter(double md) const { return SectionDiameter(SectionIndex(md), md); }

double HoleProfile::MinDiameter(double md_from, double md_to) const {
  if (md_from > md_to) std::swap(md_from, md_to);
  const std::size_t first = SectionIndex(md_from);
  const std::size_t last = SectionIndex(md_to);
  double smallest = std::numeric_limits<double>::infinity();
  for (std::size_t i = first; i <= last; ++i) {
    // Linear in each section, so its extremes sit at the ends of the overlap; a section below
    // `first` begins just past its start, whose value is the infimum there.
    const double low = (i == first) ? md_from : starts_[i];
    const double high = (i == last) ? md_to : *sections_[i].to_md;
    smallest = std::min({smallest, SectionDiameter(i, low), SectionDiameter(i, high)});
  }
  return smallest;
}

}  // namespace drillflex::well
