// Craig–Bampton reduction cost (never a timed test): build in Release and run by hand,
//   build/bench/cms_bench
// The goal (method.md §3): a 10-element body with H = 12 reduces in well under 1 ms.
#include <benchmark/benchmark.h>

#include "cms/craig_bampton.hpp"
#include "cms/reduction_cache.hpp"
#include "fe/body_fe_model.hpp"

namespace {

using namespace drillflex;

fe::BodySpec DrillPipeBody(int elements) {
  fe::BodySpec spec;
  spec.section = {0.127, 0.1086104};
  spec.material = fe::Steel();
  spec.length = 9.144;
  spec.element_count = elements;
  return spec;
}

void BM_BuildBodyFeModel(benchmark::State& state) {
  const fe::BodySpec spec = DrillPipeBody(static_cast<int>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(fe::BuildBodyFeModel(spec));
}
BENCHMARK(BM_BuildBodyFeModel)->Arg(10)->Arg(20)->Arg(1000)->Unit(benchmark::kMicrosecond);

// FE model + reduction, what the cache does on a miss.
void BM_BuildAndReduce(benchmark::State& state) {
  const fe::BodySpec spec = DrillPipeBody(static_cast<int>(state.range(0)));
  const int modes = static_cast<int>(state.range(1));
  for (auto _ : state)
    benchmark::DoNotOptimize(cms::Reduce(fe::BuildBodyFeModel(spec), modes, 0.01));
}
BENCHMARK(BM_BuildAndReduce)
    ->Args({10, 12})
    ->Args({20, 12})
    ->Args({20, 24})
    ->Unit(benchmark::kMicrosecond);

void BM_ReduceOnly(benchmark::State& state) {
  const fe::BodyFeModel model =
      fe::BuildBodyFeModel(DrillPipeBody(static_cast<int>(state.range(0))));
  for (auto _ : state) benchmark::DoNotOptimize(cms::Reduce(model, 12, 0.01));
}
BENCHMARK(BM_ReduceOnly)->Arg(10)->Unit(benchmark::kMicrosecond);

void BM_CacheHit(benchmark::State& state) {
  cms::ReductionCache cache;
  const fe::BodySpec spec = DrillPipeBody(10);
  const cms::ReductionOptions options;
  cache.Get(spec, options);
  for (auto _ : state) benchmark::DoNotOptimize(cache.Get(spec, options));
}
BENCHMARK(BM_CacheHit);

}  // namespace

BENCHMARK_MAIN();
