// The sweep (pipeline/sweep_plan.hpp, sweep_run.hpp): its values from --vary and from a table, its
// rows equal to single runs to the last digit whatever the jobs, a failed run as a row with its
// message, and a resumed sweep ending with the table an uninterrupted one writes.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "core/error.hpp"
#include "io/case.hpp"
#include "pipeline/sweep_run.hpp"
#include "../sweep_case.hpp"

namespace drillflex::pipeline {
namespace sweep_test {

namespace fs = std::filesystem;


io::Case BaseCase() { return io::ParseCase(drillflex::test_cases::kSweepCase, "sweep.yaml"); }

std::string ReadFile(const fs::path& path) {
  std::ifstream file(path);
  std::stringstream text;
  text << file.rdbuf();
  return text.str();
}

fs::path FreshDirectory(const std::string& name) {
  const fs::path directory = fs::path(DRILLFLEX_BINARY_DIR) / "sweep-test" / name;
  fs::remove_all(directory);
  return directory;
}

TEST(SweepPlan, ARangeWithAUnitAndAListExpandAsGiven) {
  const SweepAxis wob = ParseSweepAxis("operation.wob=10:40:5 klbf");
  EXPECT_EQ(wob.key, "operation.wob");
  ASSERT_EQ(wob.values.size(), 7u);
  EXPECT_EQ(wob.values.front(), "10 klbf");
  EXPECT_EQ(wob.values.back(), "40 klbf");
  // Each value from its index: 0.1 × 3 reads 0.3, and the end is included.
  const SweepAxis friction = ParseSweepAxis("model.contact.friction=0.1:0.3:0.1");
  ASSERT_EQ(friction.values.size(), 3u);
  EXPECT_EQ(friction.values[2], "0.3");
  EXPECT_EQ(ParseSweepAxis("operation.rpm = 60, 120,180").values, (std::vector<std::string>{"60", "120", "180"}));
  const std::vector<SweepCombination> combinations =
      SweepCombinations({ParseSweepAxis("a=1,2,3"), ParseSweepAxis("b=x,y")});
  ASSERT_EQ(combinations.size(), 6u);
  EXPECT_EQ(combinations[1][0].value, "1");  // the first axis varies slowest
  EXPECT_EQ(combinations[1][1].value, "y");
  EXPECT_EQ(combinations[5][0].value, "3");
}

TEST(SweepPlan, BadSpecificationsNameTheKey) {
  for (const char* spec : {"operation.wob", "=1,2", "operation.wob=", "operation.wob=10:40 klbf",
                           "operation.wob=40:10:5", "operation.wob=10:40:0", "operation.rpm=60,,120"}) {
    EXPECT_THROW(ParseSweepAxis(spec), InputError) << spec;
  }
  try {
    ParseSweepAxis("operation.wob=40:10:5 klbf");
    FAIL();
  } catch (const InputError& error) {
    EXPECT_EQ(error.key_path(), "operation.wob");
  }
  EXPECT_THROW(SweepCombinations({ParseSweepAxis("a=1"), ParseSweepAxis("a=2")}), InputError);
}

TEST(SweepPlan, ATableGivesOneRunARow) {
  const fs::path directory = FreshDirectory("table");
  fs::create_directories(directory);
  {
    std::ofstream table(directory / "cases.csv");
    table << "# a design study\noperation.wob, model.contact.friction\n20 kN, 0.2\n\n\"30 kN\", 0.3\n";
  }
  const std::vector<SweepCombination> rows = SweepRowsFromCsv((directory / "cases.csv").string());
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[1][0].key, "operation.wob");
  EXPECT_EQ(rows[1][0].value, "30 kN");
  EXPECT_EQ(rows[1][1].value, "0.3");
  {
    std::ofstream table(directory / "ragged.csv");
    table << "operation.wob,model.contact.friction\n20 kN\n";
  }
  try {
    SweepRowsFromCsv((directory / "ragged.csv").string());
    FAIL();
  } catch (const InputError& error) {
    EXPECT_EQ(error.location().line, 2);
  }
}

// A bit speed m + a sin(2π t / T) over whole periods in the second half: (max − min) / mean = 2a/m
// (the samples hit both extremes: T is a multiple of 4 output intervals).
TEST(SweepOutcome, StickSlipSeverityOfASinusoidalBitSpeed) {
  analyses::TransientResult result;
  const double mean = 10.0, amplitude = 4.0, period = 0.4, interval = 0.01;
  for (int i = 0; i <= 400; ++i) {
    analyses::TransientSample sample;
    sample.time = i * interval;
    // The first half spins up (ignored), the second oscillates.
    sample.bit_speed = i < 200 ? 0.05 * i : mean + amplitude * std::sin(2.0 * kPi * sample.time / period);
    result.samples.push_back(sample);
  }
  EXPECT_NEAR(StickSlipSeverity(result), 2.0 * amplitude / mean, 1e-9);
  for (auto& sample : result.samples) sample.bit_speed = 0.0;
  EXPECT_TRUE(std::isnan(StickSlipSeverity(result)));
}

// A 3 × 2 sweep on two jobs: each row is the single run of its values, to the last digit.
TEST(Sweep, RowsEqualSingleRunsToTheLastDigit) {
  const io::Case base = BaseCase();
  const std::vector<SweepCombination> combinations =
      SweepCombinations({ParseSweepAxis("operation.wob=20:60:20 kN"), ParseSweepAxis("operation.rpm=0,60")});
  const fs::path directory = FreshDirectory("equal");
  const std::vector<SweepRow> rows = RunSweep(base, combinations, {directory.string(), 2, false, false, {}});
  ASSERT_EQ(rows.size(), 6u);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    EXPECT_EQ(rows[i].index, static_cast<int>(i));
    ASSERT_TRUE(rows[i].outcome.converged) << rows[i].outcome.message;
    const io::Case single = io::WithValues(base, combinations[i]);
    const SweepOutcome alone = SummarizeRun(RunCase(single, CaseAnalyses(single)));
    EXPECT_EQ(rows[i].outcome.bit_side_force, alone.bit_side_force) << i;
    EXPECT_EQ(rows[i].outcome.largest_contact_force, alone.largest_contact_force) << i;
    EXPECT_EQ(rows[i].outcome.peak_von_mises_stress, alone.peak_von_mises_stress) << i;
    EXPECT_EQ(rows[i].outcome.hook_load, alone.hook_load) << i;
    EXPECT_EQ(rows[i].outcome.surface_torque, alone.surface_torque) << i;
    EXPECT_EQ(rows[i].outcome.bit_tendency, alone.bit_tendency) << i;
  }
  // The values change the answers: more WOB, more side force at the bit on the low side.
  EXPECT_NE(rows[0].outcome.bit_side_force, rows[2].outcome.bit_side_force);
  // The hook load is the buoyed weight along the hole less the WOB (frictionless statics along the
  // string: the wall's friction is around it, the string at rest axially): 20 kN more WOB, 20 kN less.
  EXPECT_NEAR(rows[0].outcome.hook_load - rows[2].outcome.hook_load, 20e3, 1.0);
  // And the hook load itself: the buoyed weight along the hole of the bit, collars and pipe and of the
  // pipe above them to the surface (300 m MD, 54.3 m modelled), less the WOB. Steel 7850 kg/m³ in
  // 1200 kg/m³ mud, g = 9.81 m/s², cos 30°; the bit a solid 0.2159 m cylinder 0.3 m long.
  auto tube = [](double od, double id) { return 9.81 * (7850.0 - 1200.0) * kPi / 4.0 * (od * od - id * id); };
  const double weight = tube(0.2159, 0.0) * 0.3 + tube(0.1715, 0.0714) * 27.0 + tube(0.127, 0.1086) * (300.0 - 27.3);
  const double expected_hook = weight * std::cos(kPi / 6.0) - 20e3;
  EXPECT_NEAR(rows[0].outcome.hook_load, expected_hook, 1e-3 * expected_hook);
  // Turning at 60 rpm, the wall's friction takes a torque the rig supplies clockwise (positive); at
  // rest none.
  EXPECT_GT(rows[1].outcome.surface_torque, 100.0);
  EXPECT_NEAR(rows[0].outcome.surface_torque, 0.0, 1e-3);
  // (The top node's section force, half an element down, read 0.34 % light: the reaction is taken.)
  // Not computed: no modes, vibration or transient in this case.
  EXPECT_TRUE(std::isnan(rows[0].outcome.first_critical_speed));
  EXPECT_TRUE(std::isnan(rows[0].outcome.stick_slip_severity));

  // The table: one row a run, the values as given, empty cells where nothing was computed.
  ComposeSweepFiles(base, rows, directory.string()).Commit();
  const std::string csv = ReadFile(directory / "sweep.csv");
  EXPECT_NE(csv.find("run,operation.wob,operation.rpm,converged,bit_side_force"), std::string::npos) << csv;
  EXPECT_NE(csv.find("\n6,60 kN,60,1,"), std::string::npos) << csv;
  EXPECT_TRUE(fs::exists(directory / "sweep.json"));
  EXPECT_FALSE(fs::exists(directory / "results.json"));
}

TEST(Sweep, ARunThatFailsIsARowWithItsMessage) {
  const std::vector<SweepCombination> combinations = SweepCombinations({ParseSweepAxis("model.contact.friction=0.3,lots")});
  const fs::path directory = FreshDirectory("failure");
  const std::vector<SweepRow> rows = RunSweep(BaseCase(), combinations, {directory.string(), 1, true, false, {}});
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_TRUE(rows[0].outcome.converged);
  EXPECT_FALSE(rows[1].outcome.converged);
  EXPECT_NE(rows[1].outcome.message.find("model.contact.friction"), std::string::npos) << rows[1].outcome.message;
  EXPECT_TRUE(std::isnan(rows[1].outcome.bit_side_force));
  // --keep-runs: the run that converged has its own files, the failed one none.
  EXPECT_TRUE(fs::exists(directory / "runs" / "0001" / "results.json"));
  EXPECT_FALSE(fs::exists(directory / "runs" / "0002"));
}

// An interrupted sweep (its journal holding two of six rows and half a line) resumed: the four
// missing runs are run, and the table is the uninterrupted sweep's, byte for byte.
TEST(Sweep, AResumedSweepEndsWithTheSameTable) {
  const io::Case base = BaseCase();
  const std::vector<SweepCombination> combinations =
      SweepCombinations({ParseSweepAxis("operation.wob=20:60:20 kN"), ParseSweepAxis("operation.rpm=0,60")});
  const fs::path whole = FreshDirectory("whole");
  const std::vector<SweepRow> all = RunSweep(base, combinations, {whole.string(), 1, false, false, {}});
  ComposeSweepFiles(base, all, whole.string()).Commit();

  const fs::path resumed = FreshDirectory("resumed");
  fs::create_directories(resumed);
  {
    std::ofstream journal(resumed / kSweepJournal);
    journal << SweepRowToJson(all[3]).dump() << '\n' << SweepRowToJson(all[0]).dump() << '\n';
    journal << SweepRowToJson(all[1]).dump().substr(0, 40);  // cut short by the interruption
  }
  int run_this_call = 0;
  const std::vector<SweepRow> rows = RunSweep(
      base, combinations,
      {resumed.string(), 1, false, true, [&](const SweepProgress& progress) { run_this_call = progress.run_this_call; }});
  EXPECT_EQ(run_this_call, 4);
  ComposeSweepFiles(base, rows, resumed.string()).Commit();
  EXPECT_EQ(ReadFile(resumed / "sweep.csv"), ReadFile(whole / "sweep.csv"));
  EXPECT_EQ(ReadFile(resumed / "sweep.json"), ReadFile(whole / "sweep.json"));

  // A journal of another sweep is refused, not mixed in.
  const std::vector<SweepCombination> other = SweepCombinations({ParseSweepAxis("operation.wob=25:65:20 kN"),
                                                                  ParseSweepAxis("operation.rpm=0,60")});
  EXPECT_THROW(RunSweep(base, other, {resumed.string(), 1, false, true, {}}), InputError);
}

}  // namespace sweep_test
}  // namespace drillflex::pipeline

namespace drillflex::pipeline {
namespace sweep_test {

// RunTasksOnThreads hands every task out once, and an exception a task throws on a worker thread comes
// back to the caller instead of ending the process.
TEST(RunTasksOnThreads, RunsEachTaskOnceAndRethrowsATasksException) {
  std::vector<std::atomic<int>> runs(50);
  RunTasksOnThreads(2, runs.size(), [&](std::size_t k) { ++runs[k]; });
  for (const auto& count : runs) EXPECT_EQ(count.load(), 1);
  EXPECT_THROW(RunTasksOnThreads(2, 50,
                                 [](std::size_t k) {
                                   if (k == 7) throw SolverError("task 7");
                                 }),
               SolverError);
}

}  // namespace sweep_test
}  // namespace drillflex::pipeline
