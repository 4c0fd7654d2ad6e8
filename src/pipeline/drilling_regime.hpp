// What a transient run did, in a driller's words: the bit turning smoothly, oscillating in torsion or
// sticking and slipping (the stick-slip severity), and the string whirling forward or backward (the
// probes' orbits). The stability map (`drillflex stability`) colours its RPM × WOB plane by it.
#pragma once

#include <string>
#include <vector>

#include "analyses/modes_analysis.hpp"
#include "analyses/transient_analysis.hpp"

namespace drillflex::pipeline {

// A run's whirl: analyses::Whirl's None, Forward or Backward (a mode's word, here of an orbit).
using analyses::Whirl;

// A severity (max − min) / mean bit speed of at least this is torsional oscillation; of at least the
// stick-slip one the bit stops (its speed swings to zero and back to twice its mean): the report's words.
inline constexpr double kTorsionalOscillationSeverity = 0.2;
inline constexpr double kStickSlipSeverity = 1.0;
// A probe whirls when its orbit stays at least this fraction of its radial clearance from the hole's
// axis all through the window (out near the wall: a string swinging through the centre in a plane
// flips its whirl angle by half a turn at each pass, which is no orbit) and its whirl angle turns at
// least once round over it.
inline constexpr double kWhirlRadiusFraction = 0.5;

struct DrillingRegime {
  double stick_slip_severity = 0.0;  // (max − min) / mean bit speed over the window (StickSlipSeverity)
  Whirl whirl = Whirl::None;
  double whirl_speed = 0.0;          // rad/s, the whirling probe's precession, clockwise looking down-hole
                                     // positive (the string's own sense of rotation); 0 without whirl
  double whirl_probe_s = 0.0;        // m from the bit, the probe it is read at
  // "smooth", "torsional oscillation" or "stick-slip", then ", forward whirl" or ", backward whirl".
  std::string Name() const;
};

// The regime over the second half of the run's samples (after the spin-up, as the report and the
// stick-slip severity take it). `probe_clearance`: each probe's radial clearance (m: the hole's radius
// less the contact circle's there). A probe's whirl speed is the least-squares slope of its unwrapped
// whirl angle; it whirls forward when that turns the same way as the bit, backward when against it.
// When probes whirl both ways, backward whirl (the damaging one) is the run's.
DrillingRegime ClassifyDrillingRegime(const analyses::TransientResult& result, const std::vector<double>& probe_clearance);

}  // namespace drillflex::pipeline
