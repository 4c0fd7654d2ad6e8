// A run's result files, composed in memory from its results (results.json, the CSV tables, and
// optionally report.html and the VTK files): the command line commits them to disk, the Python
// module reads results.json's object from them.
#pragma once

#include <string>

#include "io/case.hpp"
#include "io/result_files.hpp"
#include "pipeline/case_run.hpp"

namespace drillflex::pipeline {

struct FileOptions {
  std::string directory;      // where Commit() writes; "" = io::DefaultOutputDirectory(c)
  bool report = false;        // report.html
  bool vtk = false;           // string.vtp, well.vtp, contacts.vtp, transient.pvd
  std::string command;        // "static", "run", ...: the report's header
  double run_seconds = 0.0;   // the run's wall time: the report's header
};

// The files of `results` (nothing written yet).
io::ResultFiles ComposeResultFiles(const io::Case& c, const CaseResults& results, const FileOptions& options);

}  // namespace drillflex::pipeline
