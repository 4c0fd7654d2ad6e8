// `drillflex sweep` run as a user runs it: the same table on one job, on two, and over two MPI ranks,
// to the byte; a run that fails is a row; values that cannot be read are bad input (exit 2), nothing
// written. (Resuming: tests/pipeline/sweep_test.cpp.)
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <unistd.h>

#include <fmt/format.h>

#include "../sweep_case.hpp"
#include "cli_run.hpp"

namespace sweep_cli_test {

namespace fs = std::filesystem;


constexpr const char* kVary = "--vary 'operation.wob=20:60:20 kN' --vary operation.rpm=0,60";

using drillflex::test_cli::ReadFile;
using drillflex::test_cli::RunResult;
using drillflex::test_cli::RunShell;

fs::path Directory(const std::string& name) { return drillflex::test_cli::FreshDirectory("drillflex-sweep-cli", name); }

fs::path CaseFile() {
  const fs::path directory = fs::temp_directory_path() / "drillflex-sweep-cli";
  fs::create_directories(directory);
  const fs::path path = directory / "case.yaml";
  std::ofstream(path) << drillflex::test_cases::kSweepCase;
  return path;
}

std::string Sweep(const std::string& name, const std::string& options, const std::string& launcher = "") {
  const fs::path out = Directory(name);
  const RunResult result =
      RunShell(fmt::format("{} {} sweep {} {} -o {} {}", launcher, DRILLFLEX_EXE, CaseFile().string(), kVary, out.string(),
                      options));
  EXPECT_EQ(result.status, 0) << result.output;
  EXPECT_NE(result.output.find("sweep: 6 runs, 0 failed"), std::string::npos) << result.output;
  return ReadFile(out / "sweep.csv");
}

TEST(SweepCli, TwoJobsWriteTheSerialTable) {
  const std::string serial = Sweep("serial", "");
  ASSERT_NE(serial.find("\n6,60 kN,60,1,"), std::string::npos) << serial;
  EXPECT_EQ(Sweep("jobs", "--jobs 2"), serial);
}

#ifdef DRILLFLEX_MPIRUN
TEST(SweepCli, TwoMpiRanksWriteTheSerialTable) {
  const std::string serial = Sweep("serial-for-mpi", "");
  EXPECT_EQ(Sweep("mpi", "", fmt::format("{} --oversubscribe --allow-run-as-root -np 2", DRILLFLEX_MPIRUN)), serial);
}
#endif

TEST(SweepCli, AFailedRunIsARowAndBadValuesAreBadInput) {
  const fs::path out = Directory("failed");
  const RunResult result = RunShell(fmt::format("{} sweep {} --vary model.contact.friction=0.3,lots -o {}", DRILLFLEX_EXE,
                                           CaseFile().string(), out.string()));
  EXPECT_EQ(result.status, 0) << result.output;
  EXPECT_NE(result.output.find("2 runs, 1 failed"), std::string::npos) << result.output;
  const std::string csv = ReadFile(out / "sweep.csv");
  EXPECT_NE(csv.find("\n2,lots,0,"), std::string::npos) << csv;
  EXPECT_NE(csv.find("model.contact.friction"), csv.rfind("model.contact.friction")) << csv;  // named in the message
  const fs::path bad_out = Directory("bad");
  const RunResult bad = RunShell(fmt::format("{} sweep {} --vary operation.wob=40:10:5 -o {}", DRILLFLEX_EXE,
                                        CaseFile().string(), bad_out.string()));
  EXPECT_EQ(bad.status, 2) << bad.output;
  EXPECT_NE(bad.output.find("operation.wob"), std::string::npos) << bad.output;
  EXPECT_FALSE(fs::exists(bad_out / "sweep.csv"));
}

}  // namespace sweep_cli_test
