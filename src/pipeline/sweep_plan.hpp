// What a sweep runs: the varied keys of a case and their values, from the command line's
// `--vary KEY=VALUES` or the rows of a CSV table (`--cases table.csv`), as combinations of case values
// (io::CaseValue: a key path and a value in the case's syntax, set by io::WithValues).
#pragma once

#include <string>
#include <vector>

#include "io/case.hpp"

namespace drillflex::pipeline {

// One varied key and its values, each as the case file would give it ("10 klbf", "0.3", "40 ft").
struct SweepAxis {
  std::string key;
  std::vector<std::string> values;
};

// `KEY=VALUES`, VALUES either a list "60,120,180" (each value with its own unit, or none) or a range
// "FROM:TO:STEP UNIT" ("10:40:5 klbf", the unit optional): FROM, FROM + STEP, ... up to TO included
// when a step lands on it (within 1e-9 of the step). Throws InputError (file "--vary", key KEY): no
// '=', an empty key or value, a range that is not three numbers, a step of 0 or against TO − FROM,
// more than kMaxSweepValues values.
SweepAxis ParseSweepAxis(const std::string& spec);

inline constexpr int kMaxSweepValues = 100000;

// One run of a sweep: the case values it sets.
using SweepCombination = std::vector<io::CaseValue>;

// Every combination of the axes' values, the first axis varying slowest (as nested loops in the
// order given). Throws InputError (file "--vary") when the same key is varied twice or there would be
// more than kMaxSweepValues runs.
std::vector<SweepCombination> SweepCombinations(const std::vector<SweepAxis>& axes);

// The rows of a CSV table: a header line of key paths, then one run a line, a value a cell (a cell
// holding a comma is quoted: "a, b"). Blank lines and lines starting with '#' are skipped. Throws
// InputError naming the file and line: a row with other than the header's count of cells, an empty
// header cell, no rows.
std::vector<SweepCombination> SweepRowsFromCsv(const std::string& path);

}  // namespace drillflex::pipeline
