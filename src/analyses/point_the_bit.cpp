#include "analyses/point_the_bit.hpp"

#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "core/error.hpp"

namespace drillflex::analyses {
namespace {

constexpr double kPlaceTolerance = 1e-6;  // m: two places this close are one

// The component the fulcrum is in (the lower of two that meet there), or the string's size.
std::size_t HoldingComponent(const model::StringConfig& string, double at) {
  double top = 0.0;
  for (Index i = 0; i < std::ssize(string.components); ++i) {
    const model::Component& component = string.components[i];
    top += component.length * component.count;
    if (at <= top + kPlaceTolerance) return i;
  }
  return string.components.size();
}

}  // namespace

std::optional<std::pair<std::string, std::string>> PointTheBitProblem(const model::ModelInput& input,
                                                                      const RssSettings& rss) {
  const model::StringConfig& string = input.string;
  const std::string key = "analyses.tendency.rss.at";
  if (string.components.empty()) return std::nullopt;  // the tendency's own check says so
  const model::Component& bit = string.components.front();
  const double bit_top = bit.length * bit.count;
  const double length = model::StringLength(string);
  if (rss.at < bit_top - kPlaceTolerance || rss.at > length - kPlaceTolerance) {
    return std::make_pair(key, fmt::format("the fulcrum of a point-the-bit system ({:.4g} m from the bit) must lie "
                                           "between the bit's top ({:.4g} m) and the string's ({:.4g} m)",
                                           rss.at, bit_top, length));
  }
  const Index holder = HoldingComponent(string, rss.at);
  for (Index i = 0; i < std::ssize(string.components); ++i) {
    const model::Component& component = string.components[i];
    if (!component.bend_angle) continue;
    const bool same_place = component.bend_to_bit && std::abs(*component.bend_to_bit - rss.at) <= kPlaceTolerance;
    if (i == holder || same_place) {
      return std::make_pair(key, fmt::format("the fulcrum of a point-the-bit system ({:.4g} m from the bit) is in "
                                             "string[{}], a bent motor: put it in a component without a bend",
                                             rss.at, i));
    }
  }
  return std::nullopt;
}

model::ModelInput PointTheBit(model::ModelInput input, const RssSettings& rss, double set_toolface) {
  if (!(rss.offset > 0.0)) return input;
  const std::size_t holder = HoldingComponent(input.string, rss.at);
  if (holder >= input.string.components.size()) throw LogicError("PointTheBit: the fulcrum is beyond the string");
  model::Component& component = input.string.components[holder];
  component.bend_angle = rss.offset;
  component.bend_to_bit = rss.at;
  component.toolface = set_toolface;
  return input;
}

double TwistAt(const StaticResult& equilibrium, double s) {
  double twist = 0.0, distance = std::numeric_limits<double>::infinity();
  for (const StaticNodeResult& node : equilibrium.nodes) {
    if (std::abs(node.s - s) < distance) {
      distance = std::abs(node.s - s);
      twist = node.rotation.x();
    }
  }
  return twist;
}

std::optional<ThreePointYield> PointTheBitThreePoint(const model::StringConfig& string, const RssSettings& rss) {
  return ThreePointYieldOfBend(string, rss.at, rss.offset, rss.toolface);
}

}  // namespace drillflex::analyses
