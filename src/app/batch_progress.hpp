// The progress line of a batch of runs (a sweep, a roadmap) on standard error.
#pragma once

namespace drillflex::app {

// "sweep: 12 / 40 done, 1 failed, about 35 s left": a line redrawn on a terminal, a line every tenth
// of the batch otherwise (logs of batch jobs). `seconds_left` < 0: not known yet.
void ShowBatchProgress(const char* what, int done, int total, int failed, double seconds_left);

}  // namespace drillflex::app
