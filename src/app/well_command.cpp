// `drillflex well CASE [-o DIR]`: the well trajectory at every station and output step.
#include <iostream>

#include <fmt/format.h>

#include "app/commands.hpp"
#include "core/error.hpp"
#include "io/case.hpp"
#include "io/trajectory_table.hpp"

namespace drillflex::app {

int RunWell(const CommandOptions& options) {
  const io::Case c = io::ReadCase(options.case_path);
  if (!c.well) {
    throw InputError({c.file, 0, 0}, "well", "the case has no 'well' section: there is no trajectory to write");
  }
  const auto rows = io::TrajectoryTable(*c.well);
  io::ResultFiles files(options.output_directory.empty() ? io::DefaultOutputDirectory(c) : options.output_directory);
  files.json()["case"] = c.name;
  files.json()["units"] = units::SystemName(c.output_units);
  io::AddTrajectoryResults(rows, c.output_units, files);
  files.Commit();
  std::cout << fmt::format("well: {} rows written to {}/trajectory.csv and results.json\n", rows.size(),
                           files.directory());
  return kExitOk;
}

}  // namespace drillflex::app
