// drillflex: drill-string and BHA dynamics. `drillflex <analysis> CASE.yaml [-o OUTDIR]`.
#include <functional>
#include <iostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "app/commands.hpp"
#include "core/error.hpp"

namespace {

using drillflex::app::CommandOptions;

struct Subcommand {
  const char* name;
  const char* description;
  std::function<int(const CommandOptions&)> run;
  bool writes_results;
  bool writes_report;  // report.html and the VTK files: the commands that solve
};

// Runs a subcommand, turning every error into a message on stderr and an exit status.
int Guarded(const Subcommand& command, const CommandOptions& options) {
  using namespace drillflex;
  try {
    return command.run(options);
  } catch (const InputError& error) {
    std::cerr << "drillflex: error: " << error.what() << "\n";
    return app::kExitBadInput;
  } catch (const SolverError& error) {
    std::cerr << "drillflex: " << command.name << " did not converge: " << error.what() << "\n";
    return app::kExitNotConverged;
  } catch (const std::exception& error) {
    std::cerr << "drillflex: error: " << error.what() << "\n";
    return app::kExitFailure;
  }
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App cli{"drillflex: drill-string and BHA dynamics by flexible multibody simulation"};
  cli.require_subcommand(1);
  cli.set_version_flag("--version", "drillflex 0.1.0");

  const std::vector<Subcommand> commands = {
      {"check", "Read and validate a case; print a summary of the well, the string and the analyses",
       drillflex::app::RunCheck, false, false},
      {"well", "Write the well trajectory (trajectory.csv, results.json)", drillflex::app::RunWell, true, false},
      {"static", "Static equilibrium: deformed shape, internal forces and stresses along the string",
       drillflex::app::RunStaticCommand, true, true},
      {"modes", "Natural frequencies and mode shapes about the static equilibrium", drillflex::app::RunModesCommand,
       true, true},
      {"vibration", "Forced response against RPM: the critical-speed map, critical RPMs and safe windows",
       drillflex::app::RunVibrationCommand, true, true},
      {"buckling", "Critical load multiplier of the case's loads (eigenproblem and frequency against load)",
       drillflex::app::RunBucklingCommand, true, true},
      {"transient", "Time integration from the static equilibrium: transient.csv at the output interval",
       drillflex::app::RunTransientCommand, true, true},
      {"tendency", "Directional tendency: the steady build and turn rates the BHA drills at the bit's depth",
       drillflex::app::RunTendencyCommand, true, true},
      {"run", "Every analysis the case lists", drillflex::app::RunCaseCommand, true, true},
      {"sweep", "The case's analyses for every combination of varied values: sweep.csv, one row a run",
       drillflex::app::RunSweepCommand, true, false},
      {"roadmap", "Torque-and-drag roadmap: pick-up, slack-off and rotating hook loads and torques against bit depth",
       drillflex::app::RunRoadmapCommand, true, true},
      {"calibrate", "Fit the friction factors, hook-load offset and bit torque coefficient to the rig's readings",
       drillflex::app::RunCalibrateCommand, true, true},
      {"stability", "Stability map: the case's transient at every RPM and WOB, each run's regime (stick-slip, whirl)",
       drillflex::app::RunStabilityCommand, true, true},
      {"import", "Write a case file from WITSML 1.4.1.1 or 2.0 trajectory, tubular and wbGeometry documents",
       drillflex::app::RunImport, false, false},
  };

  CommandOptions options;
  int status = drillflex::app::kExitOk;
  for (const auto& command : commands) {
    CLI::App* sub = cli.add_subcommand(command.name, command.description);
    if (std::string(command.name) == "import") {
      sub->add_option("documents", options.documents, "WITSML documents (XML): trajectory, tubular, wbGeometry")
          ->required();
      sub->add_option("-o,--output", options.output_directory, "The case file to write (default: standard output)");
      sub->callback([&status, &options, command]() { status = Guarded(command, options); });
      continue;
    }
    sub->add_option("case", options.case_path, "Case file (YAML)")->required();
    if (command.writes_results) {
      sub->add_option("-o,--output", options.output_directory,
                      "Output directory (default: results/<case name>)");
      sub->add_flag("-v,--verbose", options.verbose, "Print the solvers' progress (stages, Newton iterations)");
      sub->add_flag("--profile", options.profile,
                    "Print where the solve spent its time (assembly, factorizations, solvers) on standard error");
      if (command.writes_report) {
        sub->add_flag("--no-report", options.no_report, "Write no report.html and no VTK files (batch runs)");
      }
    }
    const std::string name = command.name;
    if (name == "sweep" || name == "roadmap" || name == "stability" || name == "calibrate") {
      sub->add_option("-j,--jobs", options.jobs, "Runs at once on this machine (default 1)")
          ->check(CLI::Range(1, 1024));
    }
    if (name == "roadmap") {
      sub->add_option("--from", options.roadmap_from, "First bit MD, with or without a unit (default: the case's roadmap.from)");
      sub->add_option("--step", options.roadmap_step, "Depth step (default: ten depths to the case's bit MD)");
      sub->add_option("--friction", options.roadmap_friction, "Friction factors, a list: 0.2,0.3,0.4");
      sub->add_option("--model", options.roadmap_model,
                      "stiff (the case's string, default), soft (Johancsik's soft string) or both (drawn together)");
      sub->add_option("--stiff-length", options.roadmap_stiff_length,
                      "String from the bit modelled stiff, with or without a unit, or 'surface' (default: the case's "
                      "string; the pipe above by the soft string)");
    }
    if (name == "roadmap" || name == "calibrate") {
      auto* readings = sub->add_option("--readings", options.readings_path,
                                       "The rig's readings: a CSV (bit_md, activity, hook_load, surface_torque, wob, "
                                       "rpm; units on the second line) or a WITSML 1.4.1.1 / 2.0 log");
      if (name == "calibrate") readings->required();
    }
    if (name == "calibrate") {
      sub->add_option("--fit", options.calibrate_fit,
                      "Parameters to fit, a list: open_hole_friction,cased_hole_friction,hook_load_offset,"
                      "bit_torque_coefficient (default: all the readings determine)");
      sub->add_option("--model", options.calibrate_model, "stiff (the case's string, default) or soft (Johancsik)");
      sub->add_option("--stiff-length", options.roadmap_stiff_length,
                      "String from the bit modelled stiff, with or without a unit, or 'surface' (default: the case's "
                      "string; the pipe above by the soft string)");
    }
    if (name == "run") {
      sub->add_flag("--keep-finished", options.keep_finished,
                    "When an analysis fails, write the results of those that finished (results.json names the failed "
                    "ones under 'failures') and exit 3; without it a failure writes nothing");
    }
    if (name == "stability") {
      sub->add_option("--rpm", options.stability_rpm_values, "Top-drive speeds: a list (60,120) or FROM:TO:STEP (40:200:20 rpm)")
          ->required();
      sub->add_option("--wob", options.stability_wob_values, "WOBs: a list or FROM:TO:STEP (10:40:10 klbf)")->required();
    }
    if (name == "sweep" || name == "stability") {
      sub->add_flag("--keep-runs", options.keep_runs, "Keep each run's own result files under DIR/runs/NNNN/");
      sub->add_flag("--resume", options.resume, "Skip the runs an interrupted sweep into DIR finished");
    }
    if (name == "sweep") {
      sub->add_option("--vary", options.vary,
                      "KEY=VALUES: a key path of the case and its values, a list (operation.rpm=60,120,180) or a "
                      "range FROM:TO:STEP with a unit (operation.wob=10:40:5 klbf); repeated: every combination");
      sub->add_option("--cases", options.cases_table, "A CSV table: a header of key paths, one run a row");
    }
    sub->callback([&status, &options, command]() { status = Guarded(command, options); });
  }
  try {
    cli.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    const int code = cli.exit(error);
    return code == 0 ? 0 : drillflex::app::kExitBadInput;
  }
  return status;
}
