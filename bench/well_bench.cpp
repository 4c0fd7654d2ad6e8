// The closest-point query of the well path, as contact uses it: a string of N points walked
// down a 3 km 3-D well, each query warm-started from the previous answer (O(1) per query), and
// the same queries cold-started from the top of the well for comparison (O(stations)).
// Run: build/bench/well_bench   (items_per_second = queries per second)
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "well/trajectory.hpp"

namespace {

using drillflex::kDegree;
using drillflex::Vec3;
using drillflex::well::SurveyStation;
using drillflex::well::Trajectory;

// A 3 km S-shaped 3-D well: vertical to 500 m, a build and turn at ~3°/30 m to 40° inclination,
// a hold, then a drop and turn; stations every 30 m (101 stations, 100 arcs).
const Trajectory& Well() {
  static const Trajectory well = [] {
    std::vector<SurveyStation> stations;
    for (int i = 0; i <= 100; ++i) {
      const double md = 30.0 * i;
      double inclination = 0.0;
      if (md > 500.0) inclination = std::min(40.0, (md - 500.0) / 10.0);
      if (md > 2000.0) inclination = std::max(15.0, 40.0 - (md - 2000.0) / 15.0);
      const double azimuth = 30.0 + 0.02 * std::max(0.0, md - 500.0);
      stations.push_back({md, inclination * kDegree, azimuth * kDegree});
    }
    return Trajectory(stations);
  }();
  return well;
}

// N points spread evenly along the well, each up to 0.1 m off the axis in its normal plane (a
// string lying in a hole).
std::vector<Vec3> StringPoints(const Trajectory& well, int count) {
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Vec3> points;
  points.reserve(count);
  for (int i = 0; i < count; ++i) {
    const double md = well.start_md() + (i + 0.5) * (well.end_md() - well.start_md()) / count;
    const auto frame = well.Frame(md);
    const double angle = 2.0 * drillflex::kPi * unit(rng), offset = 0.1 * unit(rng);
    const Vec3 radial = std::cos(angle) * frame.high_side + std::sin(angle) * frame.right;
    points.push_back(well.Position(md) + offset * radial);
  }
  return points;
}

void BM_ClosestMdWarmWalk(benchmark::State& state) {
  const Trajectory& well = Well();
  const auto points = StringPoints(well, static_cast<int>(state.range(0)));
  long visited = 0;
  for (auto _ : state) {
    double md = well.start_md();
    for (const Vec3& p : points) {
      const auto found = well.FindClosest(p, md);
      md = found.md;
      visited += found.segments_visited;
    }
    benchmark::DoNotOptimize(md);
  }
  state.SetItemsProcessed(state.iterations() * static_cast<long>(points.size()));
  state.counters["arcs_per_query"] =
      static_cast<double>(visited) / (static_cast<double>(state.iterations()) * points.size());
}
BENCHMARK(BM_ClosestMdWarmWalk)->Arg(1000)->Arg(10000)->Arg(100000);

void BM_ClosestMdColdStart(benchmark::State& state) {
  const Trajectory& well = Well();
  const auto points = StringPoints(well, static_cast<int>(state.range(0)));
  long visited = 0;
  for (auto _ : state) {
    double sum = 0.0;
    for (const Vec3& p : points) {
      const auto found = well.FindClosest(p, well.start_md());
      sum += found.md;
      visited += found.segments_visited;
    }
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(state.iterations() * static_cast<long>(points.size()));
  state.counters["arcs_per_query"] =
      static_cast<double>(visited) / (static_cast<double>(state.iterations()) * points.size());
}
BENCHMARK(BM_ClosestMdColdStart)->Arg(10000);

// Position + frame at a given MD (what output and force evaluation ask for besides contact).
void BM_PositionAndFrame(benchmark::State& state) {
  const Trajectory& well = Well();
  double md = 0.0;
  for (auto _ : state) {
    md = md > 2990.0 ? 0.0 : md + 0.37;
    benchmark::DoNotOptimize(well.Position(md));
    benchmark::DoNotOptimize(well.Frame(md));
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_PositionAndFrame);

}  // namespace

BENCHMARK_MAIN();
