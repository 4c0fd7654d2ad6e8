#include "model/contact_circles.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "model/string_geometry.hpp"

namespace drillflex::model {
namespace {

constexpr double kMinimumShare = 1.0 / 16.0;  // of a node's span, the least a circle stands for

// A tool joint or a stabilizer's blades: [from, to] along the string (m), its diameter (m), and
// the point its circle goes nearest to (the connection; the middle of the blades).
struct Feature {
  double from = 0.0, to = 0.0, diameter = 0.0, point = 0.0;
};

// Every feature of the string, clipped to its component (a joint at a component's end or the
// string's top is half inside it).
std::vector<Feature> Features(const StringConfig& string) {
  std::vector<Feature> features;
  double start = 0.0;
  for (const Component& component : string.components) {
    const double span = component.length * component.count;
    if (component.blade_diameter) {
      const double blades = component.blade_length.value_or(component.length);
      for (int item = 0; item < component.count; ++item) {
        const double middle = start + (item + 0.5) * component.length;
        features.push_back({middle - 0.5 * blades, middle + 0.5 * blades, *component.blade_diameter, middle});
      }
    }
    if (component.joint_diameter) {
      const double spacing = component.joint_spacing.value_or(std::min(kDefaultJointSpacing, component.length));
      const double half_joint = 0.5 * component.joint_length.value_or(kDefaultJointLength);
      const Index joints = std::lround(span / spacing);
      for (Index j = 0; j <= joints; ++j) {
        const double connection = start + std::min(j * spacing, span);
        features.push_back({std::max(connection - half_joint, start), std::min(connection + half_joint, start + span),
                            *component.joint_diameter, connection});
      }
    }
    start += span;
  }
  return features;
}

double Overlap(double a0, double a1, double b0, double b1) { return std::max(0.0, std::min(a1, b1) - std::max(a0, b0)); }

}  // namespace

std::vector<ContactCircle> ContactCircles(const StringConfig& string, const std::vector<double>& s) {
  if (s.empty()) throw LogicError("ContactCircles: no contact nodes");
  const Index count = std::ssize(s);
  std::vector<double> from(s.size()), to(s.size());
  for (Index i = 0; i < count; ++i) {
    if (i > 0 && s[i] < s[i - 1]) throw LogicError("ContactCircles: the contact positions are not ascending");
    from[i] = i > 0 ? 0.5 * (s[i - 1] + s[i]) : s[i];
    to[i] = i + 1 < count ? 0.5 * (s[i] + s[i + 1]) : s[i];
  }
  std::vector<ContactCircle> circles(s.size());
  std::vector<bool> feature_node(s.size(), false);
  const std::vector<Feature> features = Features(string);
  for (const Feature& feature : features) {
    if (feature.to <= s.front() - 1e-9 || feature.from >= s.back() + 1e-9) continue;  // beyond the contacts (the bit)
    const auto above = std::lower_bound(s.begin(), s.end(), feature.point);
    Index node = above - s.begin();
    if (node == count || (node > 0 && feature.point - s[node - 1] < s[node] - feature.point)) --node;
    circles[node].diameter = std::max(circles[node].diameter, feature.diameter);
    circles[node].length += feature.to - feature.from;
    feature_node[node] = true;
  }
  for (Index i = 0; i < count; ++i) {
    const double span = to[i] - from[i];
    if (!feature_node[i]) {
      double body = span;
      for (const Feature& feature : features) body -= Overlap(from[i], to[i], feature.from, feature.to);
      circles[i].diameter = ComponentAt(string, s[i]).outer_diameter;
      circles[i].length = std::max(body, kMinimumShare * span);
    }
    if (count == 1 && circles[i].length <= 0.0) circles[i].length = 1.0;  // a lone circle: the reference metre
  }
  return circles;
}

}  // namespace drillflex::model
