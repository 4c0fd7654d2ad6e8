#include "analyses/tendency_analysis.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <utility>

#include <fmt/format.h>

#include "analyses/point_the_bit.hpp"
#include "core/error.hpp"

namespace drillflex::analyses {
namespace {

using Vec2 = Eigen::Vector2d;
using Mat2 = Eigen::Matrix2d;

Vec2 AsVector(const HoleCurvature& curvature) { return {curvature.build, curvature.right}; }
HoleCurvature AsCurvature(const Vec2& v) { return {v.x(), v.y()}; }

double InDegreesPer100Ft(double curvature) { return curvature / kDegreesPer100Ft; }

// A static solved in a hole, with what a later static of the same variant starts from.
struct Solved {
  Vec2 curvature;
  std::shared_ptr<const model::Wellbore> hole;  // the one its model's input and contacts share
  std::shared_ptr<const model::BuiltModel> built;
  VecX q;
};

// One evaluated curvature: the point (averaged over the variants) and the first variant's equilibrium.
struct Evaluated {
  TendencyPoint point;
  StaticResult equilibrium;
};

// The strings whose deviation a point averages, with their weights: the case's alone; a rotating bent
// motor's bend at kRotatingToolfaces toolfaces a quarter turn apart (the bend sweeps them all in a
// revolution; four samples average the deviation exactly up to its third harmonic in the toolface);
// a rotary steerable system neutral for 1 − steer of the time and steering for `steer` of it (a
// point-the-bit system's steering string is bent at its fulcrum when each static is solved, against the
// twist there: Search::Solve).
constexpr int kRotatingToolfaces = 4;
constexpr std::size_t kKeptStatics = 3;  // a variant's statics kept as warm starts

struct Variant {
  model::ModelInput input;
  double weight = 1.0;
  bool pointing = false;  // the string of a point-the-bit system steering: bent at its fulcrum when solved
};

// The string with the RSS steering: the pads' force toward the toolface at `at` (string frame: y right,
// z high side; a dead load, its direction kept in space as the housing keeps it).
model::ModelInput Steering(model::ModelInput input, const RssSettings& rss) {
  model::Load pads;
  pads.at = rss.at;
  pads.force = Vec3(0.0, rss.force * std::sin(rss.toolface), rss.force * std::cos(rss.toolface));
  input.loads.push_back(pads);
  return input;
}

std::vector<Variant> Variants(const model::ModelInput& input, const TendencySettings& settings) {
  if (settings.rss) {
    std::vector<Variant> variants;
    if (settings.rss->steer < 1.0) variants.push_back({input, 1.0 - settings.rss->steer});
    if (settings.rss->steer > 0.0) {
      if (settings.rss->type == RssType::Point) {
        variants.push_back({input, settings.rss->steer, settings.rss->offset > 0.0});
      } else {
        variants.push_back({Steering(input, *settings.rss), settings.rss->steer});
      }
    }
    return variants;
  }
  if (!(input.operation.rotary_speed > 0.0)) return {{input, 1.0}};
  for (Index i = 0; i < std::ssize(input.string.components); ++i) {
    const model::Component& component = input.string.components[i];
    if (!component.bend_angle || !(*component.bend_angle > 0.0)) continue;
    std::vector<Variant> variants;
    for (int k = 0; k < kRotatingToolfaces; ++k) {
      model::ModelInput variant = input;
      variant.string.components[i].toolface =
          std::fmod(component.toolface.value_or(0.0) + 2.0 * kPi * k / kRotatingToolfaces, 2.0 * kPi);
      variants.push_back({std::move(variant), 1.0 / kRotatingToolfaces});
    }
    return variants;
  }
  return {{input, 1.0}};
}

class Search {
 public:
  Search(const model::ModelInput& input, const ModelFactory& build, const StaticSettings& statics,
         const TendencySettings& settings)
      : input_(input), build_(build), statics_(statics), settings_(settings), variants_(Variants(input, settings)),
        solved_(variants_.size()), bit_md_(input.bit_md), model_length_(model::StringLength(input.string)),
        top_md_(std::max(0.0, input.bit_md - model_length_ - kTendencyHoleAboveTop)),
        formation_(settings.formation
                       ? FormationDeviation(*settings.formation, input.well->trajectory.Frame(input.bit_md))
                       : HoleCurvature{}) {}

  int variant_count() const { return std::ssize(variants_); }
  int statics() const { return statics_count_; }
  int toolfaces() const { return settings_.rss ? 1 : variant_count(); }

  const Evaluated& Evaluate(const Vec2& kappa) {
    const double arc = TendencyArcLength(input_.string, kappa.norm());
    const auto hole = std::make_shared<const model::Wellbore>(model::Wellbore{
        ConstantCurvatureHole(input_.well->trajectory, bit_md_, top_md_, arc, AsCurvature(kappa)), input_.well->hole});
    TendencyPoint point;
    point.curvature = AsCurvature(kappa);
    StaticResult first;
    for (Index v = 0; v < std::ssize(variants_); ++v) {
      const double share = variants_[v].weight;
      StaticResult equilibrium = Solve(v, kappa, hole);
      const BitReport& bit = *equilibrium.bit;
      point.bit.build_force += share * bit.build_force;
      point.bit.walk_force += share * bit.walk_force;
      point.bit.tilt += share * bit.tilt;
      point.bit.tilt_right += share * bit.tilt_right;
      if (v == 0) {
        point.method = equilibrium.method;
        first = std::move(equilibrium);
      }
    }
    point.bit.side_force = std::hypot(point.bit.build_force, point.bit.walk_force);
    const double per_force = settings_.steerability / input_.operation.weight_on_bit;
    point.deviation_build = point.bit.tilt + per_force * point.bit.build_force + formation_.build;
    point.deviation_right = point.bit.tilt_right + per_force * point.bit.walk_force + formation_.right;
    if (statics_.log) {
      statics_.log(fmt::format("tendency: {:+.4f} deg/100 ft build, {:+.4f} right: side force {:+.4g} N build, "
                               "{:+.4g} N right; tilt {:+.4e}, {:+.4e} rad; deviation {:+.4e}, {:+.4e} rad ({}{})",
                               InDegreesPer100Ft(kappa.x()), InDegreesPer100Ft(kappa.y()), point.bit.build_force,
                               point.bit.walk_force, point.bit.tilt, point.bit.tilt_right, point.deviation_build,
                               point.deviation_right, point.method,
                               variants_.size() > 1 ? fmt::format(", the mean of {} statics", variants_.size()) : ""));
    }
    evaluated_.push_back(Evaluated{std::move(point), std::move(first)});
    return evaluated_.back();
  }

  std::vector<Evaluated>& evaluated() { return evaluated_; }

 private:
  // The static of variant v in `hole` (of curvature kappa): from the nearest of its own statics
  // carried into the hole when it is within kTendencyWarmStep, else from the string resting on the wall.
  // A point-the-bit system's bend is set at its toolface plus the string's twist at the fulcrum (the
  // last static's), and solved again from there while the twist moves it by more than
  // kPointToolfaceTolerance: the housing holds the toolface in space, whatever the string's twist.
  StaticResult Solve(std::size_t v, const Vec2& kappa, const std::shared_ptr<const model::Wellbore>& hole) {
    const Variant& variant = variants_[v];
    const Solved* nearest = nullptr;
    for (const Solved& solved : solved_[v]) {
      const double distance = (solved.curvature - kappa).norm();
      if (distance <= kTendencyWarmStep && (!nearest || distance < (nearest->curvature - kappa).norm())) nearest = &solved;
    }
    std::optional<VecX> start;
    std::shared_ptr<const model::BuiltModel> built;
    StaticResult equilibrium;
    for (int round = 0;; ++round) {
      model::ModelInput hole_input =
          variant.pointing ? PointTheBit(variant.input, *settings_.rss, settings_.rss->toolface + twist_) : variant.input;
      hole_input.well = hole;
      built = std::make_shared<const model::BuiltModel>(build_(hole_input));
      if (round == 0 && nearest) {
        start = CarryIntoHole(nearest->built->system, nearest->q, built->system, bit_md_, nearest->hole->trajectory,
                              hole->trajectory);
      }
      try {
        equilibrium = RunStaticInWell(hole_input, *built, statics_, 1.0, start ? &*start : nullptr);
      } catch (const SolverError& e) {
        throw SolverError(fmt::format("tendency: the static in a hole of {:.4g} deg/100 ft build, {:.4g} deg/100 ft "
                                      "right failed: {}",
                                      InDegreesPer100Ft(kappa.x()), InDegreesPer100Ft(kappa.y()), e.what()));
      }
      ++statics_count_;
      if (!variant.pointing) break;
      const double twist = TwistAt(equilibrium, settings_.rss->at);
      if (std::abs(twist - twist_) <= kPointToolfaceTolerance || round + 1 >= kPointTwistRounds) break;
      twist_ = twist;
      start = equilibrium.q;  // the same hole, the bend turned a little
    }
    if (!equilibrium.bit) throw LogicError("RunTendency: the static has no bit report");
    // The last few only: a warm start is a neighbour of a recent point (the differences of the first,
    // the last step's), and each keeps a model (hundreds of MB over a search on a long string).
    std::vector<Solved>& kept = solved_[v];
    kept.push_back(Solved{kappa, hole, std::move(built), equilibrium.q});
    if (kept.size() > kKeptStatics) kept.erase(kept.begin());
    return equilibrium;
  }

  const model::ModelInput& input_;
  const ModelFactory& build_;
  const StaticSettings& statics_;
  const TendencySettings& settings_;
  const std::vector<Variant> variants_;
  std::vector<std::vector<Solved>> solved_;  // per variant
  const double bit_md_;
  const double model_length_;
  const double top_md_;
  const HoleCurvature formation_;  // δ, rad
  std::vector<Evaluated> evaluated_;
  double twist_ = 0.0;   // rad: the string's twist at a point-the-bit system's fulcrum, the last static's
  int statics_count_ = 0;
};

Vec2 Deviation(const TendencyPoint& point) { return {point.deviation_build, point.deviation_right}; }

std::string DescribeEnd(const TendencyPoint& point) {
  return fmt::format("at {:+.0f} deg/100 ft the bit deviates {:+.4e} rad toward the high side with a side force of "
                     "{:+.4g} N toward the high side",
                     InDegreesPer100Ft(point.curvature.build), point.deviation_build, point.bit.build_force);
}

// Newton's proposal with each component kept inside the bracket the statics so far give it: the
// nearest curvatures on either side of the current one where that component of the deviation has
// the other sign (among the statics at about the current value of the other component). Outside it (a contact that opened or closed between), the component goes to the
// bracket's regula falsi point, kept a tenth of the bracket from its ends so that the bracket shrinks.
Vec2 KeepInBrackets(const std::vector<Evaluated>& evaluated, const Vec2& current, Vec2 proposal) {
  for (int j = 0; j < 2; ++j) {
    const Evaluated* positive = nullptr;
    const Evaluated* negative = nullptr;
    for (const Evaluated& e : evaluated) {
      // Only statics at (about) the current value of the other component bracket this one.
      if (std::abs(AsVector(e.point.curvature)[1 - j] - current[1 - j]) > kTendencyWarmStep) continue;
      const double value = Deviation(e.point)[j];
      const Evaluated*& side = value > 0.0 ? positive : negative;
      if (value == 0.0) continue;
      if (!side || std::abs(AsVector(e.point.curvature)[j] - current[j]) <
                       std::abs(AsVector(side->point.curvature)[j] - current[j])) {
        side = &e;
      }
    }
    if (!positive || !negative) continue;
    const double a = AsVector(positive->point.curvature)[j], b = AsVector(negative->point.curvature)[j];
    const double lo = std::min(a, b), hi = std::max(a, b);
    if (hi - lo < kTendencyCurvatureTolerance || (proposal[j] > lo && proposal[j] < hi)) continue;
    const double da = Deviation(positive->point)[j], db = Deviation(negative->point)[j];
    const double falsi = a - da * (b - a) / (db - da);
    proposal[j] = std::clamp(falsi, lo + 0.1 * (hi - lo), hi - 0.1 * (hi - lo));
  }
  return proposal;
}

}  // namespace

HoleCurvature FormationDeviation(const FormationSettings& formation, const well::PathFrame& bit) {
  // The bedding's normal: vertical for flat beds, tilted away from the dip's direction by the dip
  // (global x north, y east, z down).
  Vec3 normal(-std::sin(formation.dip) * std::cos(formation.dip_azimuth),
              -std::sin(formation.dip) * std::sin(formation.dip_azimuth), std::cos(formation.dip));
  const Vec3& b = bit.tangent;
  if (b.dot(normal) < 0.0) normal = -normal;
  const double cosine = b.dot(normal);
  const Vec3 across = 2.0 * formation.anisotropy * cosine * (normal - cosine * b);
  return {across.dot(bit.high_side), across.dot(bit.right)};
}

double TendencyArcLength(const model::StringConfig& string, double curvature) {
  const double length = model::StringLength(string) + kTendencyHoleAboveTop;
  double bha = 0.0;
  for (const model::Component& component : string.components) {
    if (component.type == model::ComponentType::Pipe) break;
    bha += component.length * component.count;
  }
  if (!(curvature > 0.0)) return length;
  const double quarter_turn = 0.5 * kPi / curvature;
  return std::min({length, std::max(bha, quarter_turn), 0.9 * kPi / curvature});
}

std::optional<std::pair<std::string, std::string>> TendencyInputProblem(const model::ModelInput& input) {
  if (!input.well || input.well->hole.empty()) {
    return std::make_pair(std::string("well"), std::string("a tendency needs a well (survey and hole): the bit "
                                                            "drills a hole, the string lies in it"));
  }
  if (input.string.components.empty() || input.string.components.front().type != model::ComponentType::Bit) {
    return std::make_pair(std::string("string"),
                          std::string("a tendency needs a bit at the bottom of the string (its first component, type bit)"));
  }
  if (!(input.operation.weight_on_bit > 0.0)) {
    return std::make_pair(std::string("operation.wob"),
                          std::string("a tendency needs a weight on bit above 0 (or a hook load that leaves one): the "
                                      "bit's side force acts against it"));
  }
  if (!input.supports.empty()) {
    return std::make_pair(std::string("supports"),
                          std::string("a tendency holds the bit at the hole's centre on the default well supports: "
                                      "remove `supports`"));
  }
  return std::nullopt;
}

TendencyResult RunTendency(const model::ModelInput& input, const ModelFactory& build, const StaticSettings& statics,
                           const TendencySettings& settings, std::optional<HoleCurvature> first) {
  if (const auto problem = TendencyInputProblem(input)) throw InputError({}, problem->first, problem->second);
  if (!(settings.steerability >= 0.0) || !std::isfinite(settings.steerability)) {
    throw InputError({}, "analyses.tendency.steerability", "the steerability must be a number >= 0");
  }
  if (settings.rss && settings.rss->type == RssType::Point) {
    if (const auto problem = PointTheBitProblem(input, *settings.rss)) {
      throw InputError({"", settings.rss->source_line, 0}, problem->first, problem->second);
    }
  }
  Search search(input, build, statics, settings);

  Vec2 kappa = AsVector(first.value_or(CurvatureAtBit(input.well->trajectory, input.bit_md)));
  kappa = kappa.cwiseMax(-kTendencyCurvatureLimit).cwiseMin(kTendencyCurvatureLimit);
  const auto deviation_at = [&](const Vec2& at) { return Deviation(search.Evaluate(at).point); };
  Vec2 d = deviation_at(kappa);
  // The Jacobian ∂d/∂κ by forward differences, then Broyden's update with every step.
  Mat2 jacobian;
  for (int j = 0; j < 2; ++j) {
    Vec2 step = Vec2::Zero();
    step[j] = kappa[j] + kTendencyDifferenceStep > kTendencyCurvatureLimit ? -kTendencyDifferenceStep
                                                                           : kTendencyDifferenceStep;
    jacobian.col(j) = (deviation_at(kappa + step) - d) / step[j];
  }
  Index answer = 0;  // index of the current point in search.evaluated()
  int outward = 0;         // consecutive steps that wanted to leave the range
  bool converged = false;
  while (std::ssize(search.evaluated()) < kTendencyEvaluations) {
    if (std::abs(jacobian.determinant()) < 1e-300 || !jacobian.allFinite()) {
      throw SolverError("tendency: the bit's deviation does not change with the hole's curvature (a singular Jacobian)");
    }
    Vec2 step = -jacobian.inverse() * d;
    if (step.norm() < kTendencyCurvatureTolerance) {
      converged = true;
      break;
    }
    if (step.norm() > kTendencyStepLimit) step *= kTendencyStepLimit / step.norm();
    const Vec2 wanted = KeepInBrackets(search.evaluated(), kappa, kappa + step);
    const Vec2 bounded = wanted.cwiseMax(-kTendencyCurvatureLimit).cwiseMin(kTendencyCurvatureLimit);
    outward = (bounded - wanted).norm() > 0.0 && (bounded - kappa).norm() < kTendencyCurvatureTolerance ? outward + 1 : 0;
    if (outward >= 2) break;
    step = bounded - kappa;
    const Vec2 d_next = deviation_at(bounded);
    // Broyden: J ← J + ((Δd − J Δκ) Δκᵀ) / (Δκᵀ Δκ).
    jacobian += ((d_next - d) - jacobian * step) * step.transpose() / step.squaredNorm();
    kappa = bounded;
    d = d_next;
    answer = std::ssize(search.evaluated()) - 1;
  }
  if (!converged) {
    // No root found: the deviation at both ends of the range says which way the bit goes there.
    const Vec2 low(-kTendencyCurvatureLimit, kappa.y()), high(kTendencyCurvatureLimit, kappa.y());
    const TendencyPoint at_low = search.Evaluate(low).point;
    const TendencyPoint at_high = search.Evaluate(high).point;
    throw SolverError(fmt::format("tendency: no steady curvature within ±30 deg/100 ft after {} statics: {}; {}",
                                  search.statics(),
                                  DescribeEnd(at_low), DescribeEnd(at_high)));
  }
  Evaluated& steady = search.evaluated()[answer];
  TendencyResult result;
  result.curvature = steady.point.curvature;
  result.inclination = input.well->trajectory.Inclination(input.bit_md);
  result.azimuth = input.well->trajectory.Azimuth(input.bit_md);
  result.build_rate = result.curvature.build;
  const double sine = std::sin(result.inclination);
  result.turn_rate = sine > 1e-3 ? result.curvature.right / sine : 0.0;
  result.dogleg_severity = std::hypot(result.curvature.build, result.curvature.right);
  result.steerability = settings.steerability;
  result.weight_on_bit = input.operation.weight_on_bit;
  result.arc_length = TendencyArcLength(input.string, result.dogleg_severity);
  result.toolfaces = search.toolfaces();
  for (const Evaluated& e : search.evaluated()) result.trace.push_back(e.point);
  result.statics = search.statics();
  result.steady_index = answer;
  result.equilibrium = std::move(steady.equilibrium);
  result.three_point = settings.rss && settings.rss->type == RssType::Point
                            ? PointTheBitThreePoint(input.string, *settings.rss)
                            : ComputeThreePointYield(input.string);
  return result;
}

}  // namespace drillflex::analyses
