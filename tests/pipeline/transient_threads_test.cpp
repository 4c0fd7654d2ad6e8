// Thread-count independence of a whole transient run (issue 6: "same results with 1 and 2 threads,
// to the last printed digit"): the bundled example's rotating bench case
// (bench/cases/rotary-bha-rotating.yaml: 104 bodies, 1872 coordinates, 1013 wall contacts, above
// the 32 bodies from which the model assembles on OpenMP threads) spun up by the top drive, run on
// 1 and on 2 threads from the same static equilibrium; transient.csv (every sample printed at full
// precision) must be identical byte for byte, and so must the step statistics and the final state.
// The run is cut to 10 ms with a 20 ms ramp so that the top turns (60 rpm at the end) and the wall
// contacts carry load, in about a second a run (the start equilibrium, solved once, another 1.5 s).
#include <gtest/gtest.h>
#include <omp.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "io/analysis_results.hpp"
#include "io/case.hpp"
#include "io/result_files.hpp"
#include "pipeline/case_run.hpp"

namespace drillflex::io {
namespace transient_threads_test {


std::string ReadFile(const std::filesystem::path& path) {
  std::ifstream file(path);
  std::stringstream text;
  text << file.rdbuf();
  return text.str();
}

struct ThreadRun {
  std::string csv;
  analyses::TransientResult result;
};

ThreadRun RunOnThreads(int threads, const Case& c, const model::BuiltModel& moving, const VecX& start,
                 const analyses::TransientSettings& settings) {
  const int previous = omp_get_max_threads();
  omp_set_num_threads(threads);
  ThreadRun run;
  run.result = analyses::RunTransient(moving, start, settings);
  omp_set_num_threads(previous);
  const std::filesystem::path directory =
      std::filesystem::path(DRILLFLEX_BINARY_DIR) / "transient-threads-test" / std::to_string(threads);
  ResultFiles files(directory.string());
  AddTransientResults(c, run.result, files);
  files.Commit();
  run.csv = ReadFile(directory / "transient.csv");
  return run;
}

TEST(TransientThreads, RotatingBundledExampleIsIdenticalOnOneAndTwoThreads) {
  // (A path object, not std::string + "...": GCC 12 at -O3 then warns of a memcpy out of bounds,
  // -Warray-bounds, a false positive of libstdc++'s inlined string concatenation.)
  Case c = ReadCase((std::filesystem::path(DRILLFLEX_SOURCE_DIR) / "bench/cases/rotary-bha-rotating.yaml").string());
  analyses::TransientSettings& settings = *c.analyses.transient;
  settings.duration = 0.01;
  settings.output_interval = 5e-4;
  settings.probes = {3.0 * 0.3048, 60.0 * 0.3048};  // the near-bit stabilizer's blade (on the wall), the MWD
  ASSERT_TRUE(settings.top_drive.has_value());
  settings.top_drive->setting.ramp_time = 0.02;
  // The transient's model and start as the command line sets them up, with the drilling fluid moving
  // with the bodies (model/fluid_inertia.hpp).
  pipeline::CaseModel case_model = pipeline::BuildCaseModel(c);
  const pipeline::TransientSetup setup = pipeline::PrepareTransient(c, case_model, nullptr, {});
  ASSERT_GT(setup.fluid_frequency, 0.0);
  ASSERT_GE(setup.moving.system.bodies().size(), 32u);  // the model's parallel assembly (system_model.cpp)

  const ThreadRun one = RunOnThreads(1, c, setup.moving, setup.start, setup.settings);
  const ThreadRun two = RunOnThreads(2, c, setup.moving, setup.start, setup.settings);

  // The run is not trivial: the top turns, some wall contact at a probe carries load, the steps adapt.
  const analyses::TransientSample& last = one.result.samples.back();
  EXPECT_NEAR(last.surface_speed, 0.5 * 120.0 * kPi / 30.0, 0.05 * 120.0 * kPi / 30.0);
  bool loaded_contact = false;
  for (const analyses::TransientSample& sample : one.result.samples) {
    for (const analyses::ProbeSample& probe : sample.probes) loaded_contact = loaded_contact || probe.contact_force > 0.0;
  }
  EXPECT_TRUE(loaded_contact);
  EXPECT_GT(one.result.statistics.steps, 10);
  EXPECT_EQ(one.result.samples.size(), 21u);

  EXPECT_EQ(one.result.statistics.steps, two.result.statistics.steps);
  EXPECT_EQ(one.result.statistics.newton_iterations, two.result.statistics.newton_iterations);
  EXPECT_EQ(one.result.statistics.factorizations, two.result.statistics.factorizations);
  ASSERT_FALSE(one.csv.empty());
  EXPECT_TRUE(one.csv == two.csv) << "transient.csv differs between 1 and 2 threads";
  EXPECT_TRUE(one.result.final_q == two.result.final_q);
  EXPECT_TRUE(one.result.final_v == two.result.final_v);
}

}  // namespace transient_threads_test
}  // namespace drillflex::io
