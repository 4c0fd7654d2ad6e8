// The torque-and-drag roadmap: at each bit depth from a start to the case's bit MD, for each friction
// factor, the hook loads pulling out (pick-up), running in (slack-off) and rotating off bottom, and
// the surface torque off and on bottom, each a static run of the stiff-string model (contacts, tool
// joints, buckling where it occurs) of the case's string (or as much of it as the settings' stiff_length
// asks), the pipe above it continued to the surface by the soft string.
#pragma once

#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "analyses/analysis_settings.hpp"
#include "analyses/string_limits.hpp"
#include "io/case.hpp"
#include "io/result_files.hpp"

namespace drillflex::pipeline {

// A run's screens on its own stations (analyses/string_limits.hpp): the buckled zones (MD from–to),
// and for a rotating run the bending stress's fatigue utilisation in each dogleg the string turns
// through and its worst station (limit "" and NaN: not rotating, or no station rated).
struct RunScreen {
  std::vector<analyses::BuckledZone> zones;
  std::vector<analyses::DoglegFatigue> doglegs;
  analyses::LimitUtilisation fatigue;
};
// The four runs' (pick-up and slack-off off bottom, rotating off bottom, on bottom).
struct PointScreens {
  RunScreen pick_up, slack_off, rotating, on_bottom;
};
// The screens of one run's stations (from the bit up: s, MD, axial force, torque, bending moment) of
// `input`'s string (the case at the point's depth to the surface: CaseAtDepth), rotating or not.
RunScreen ScreenRun(const model::ModelInput& input, const std::vector<analyses::StaticNodeResult>& stations,
                    bool rotating);

// One depth and friction factor. Hook loads in N (tension at the surface), torques in N·m (positive
// clockwise looking down-hole: the rig's). A run that failed leaves its own quantities NaN and says
// why in `message` (the runs' reasons joined by "; "); the others stand. A run answered with a
// warning (a rotating string's equilibrium at rest where its friction found no static balance) keeps
// its values and adds the warning to `message`.
struct RoadmapPoint {
  double bit_md = 0.0;
  double friction = 0.0;
  double pick_up = 0.0;
  double slack_off = 0.0;
  double rotating = 0.0;
  double off_bottom_torque = 0.0;
  double on_bottom_torque = 0.0;  // at the case's WOB and TOB
  std::string message;
  // The stiff model's screens of its own runs (RunRoadmap: the stiff part's statics, the pipe above them
  // by the soft string that carries their top to the surface); a failed run's are empty. None: the soft
  // roadmap's point (RoadmapPointLimits screens the soft string's runs).
  std::optional<PointScreens> screens;
  // A run of the point failed: one of its values is NaN (a warning alone leaves them whole).
  bool failed() const;
};

// The string's limits at a point (issue 37), NaN where none applies. Hook loads in N, torques in N·m.
struct RoadmapLimits {
  // The hook load at which the pipe at the surface (the case's top component) reaches yield / design
  // factor by von Mises under the point's off-bottom torque (model::TensionCapacity on its rated section;
  // yield E-75's for a component of no grade).
  double hook_load_limit = std::numeric_limits<double>::quiet_NaN();
  // The weakest make-up torque the string's components give (none given: NaN).
  double torque_limit = std::numeric_limits<double>::quiet_NaN();
  // Slacking off with weight set down on bottom: the hook load at which the soft string (analyses/
  // soft_string.hpp, the point's friction factor) first reaches Chen's helical load anywhere
  // (analyses/string_limits.hpp's screen); the slack-off hook load itself when it is helically buckled
  // off bottom; NaN when all its weight on the bit does not reach it.
  double helical_slack_off = std::numeric_limits<double>::quiet_NaN();
  // The screens of the point's four runs at its friction factor: pulling out (pick-up) and running in
  // (slack-off) off bottom, rotating off bottom, and drilling on bottom at the case's WOB and torque on
  // bit: the stiff model's own (point.screens), else the soft string's (Johancsik, analyses/soft_string.hpp).
  PointScreens screens;
  // The worst fatigue utilisation of the rotating runs (off bottom, on bottom) and its MD, m (NaN: none).
  double fatigue_rotating = std::numeric_limits<double>::quiet_NaN();
  double fatigue_rotating_md = std::numeric_limits<double>::quiet_NaN();
  double fatigue_on_bottom = std::numeric_limits<double>::quiet_NaN();
  double fatigue_on_bottom_md = std::numeric_limits<double>::quiet_NaN();
};
RoadmapLimits RoadmapPointLimits(const io::Case& c, const analyses::RoadmapSettings& settings,
                                 const RoadmapPoint& point);

// The casing worn drilling the roadmap's section down to a point's depth (issue 37; White & Dawson,
// pipeline/casing_wear_run.hpp, with the case's limits.wear: its factor and rpm): from one depth of the
// roadmap to the next the string rotates on bottom at the next depth for Δ depth / ROP (limits.wear.rop),
// the side force per length the soft string's there (Johancsik, at the point's friction factor in open
// hole and the settings' cased_friction, else each cased section's own), whichever model the roadmap
// runs; the first depth has drilled nothing. The deepest groove so far (NaN without limits.wear.rop or
// a cased section, or where nothing is worn).
struct RoadmapWear {
  double rotating_time = std::numeric_limits<double>::quiet_NaN();  // s, drilled since the first depth
  double md = std::numeric_limits<double>::quiet_NaN();             // m, the deepest groove's
  double side_force_per_length = std::numeric_limits<double>::quiet_NaN();  // N/m, the largest there
  double worn_area = std::numeric_limits<double>::quiet_NaN();      // m²
  double groove_depth = std::numeric_limits<double>::quiet_NaN();   // m
  double remaining_wall = std::numeric_limits<double>::quiet_NaN(); // m (NaN: no wall given)
  double utilisation = std::numeric_limits<double>::quiet_NaN();    // groove / wall (NaN: no wall given)
};
// One a point of `points` (RoadmapDepths × friction factors, in RunRoadmap's order), accumulated
// friction factor by friction factor down the depths.
std::vector<RoadmapWear> RoadmapCasingWear(const io::Case& c, const analyses::RoadmapSettings& settings,
                                           const std::vector<RoadmapPoint>& points);

// The case at `bit_md`: its well's bit MD moved there and the string's top component continued to the
// surface: a single joint (count 1) lengthened to reach it, else as many joints as fit below it (what
// is left, less than a joint, counts as the pipe above the model, model::StringAboveWeight). Throws
// InputError (file, "string") when the components below the top one leave no room for it.
io::Case CaseAtDepth(const io::Case& c, double bit_md);
// The case at `bit_md` as the stiff model of a roadmap takes it: its string cut, or its top component
// continued as CaseAtDepth does, to the settings' stiff_length from the bit (0: the case's own string's
// length; infinity: to the surface), and at least to a stand above the highest point in compression of
// the soft string slacking off at the largest friction factor or rotating on bottom at the case's WOB
// (the stiff part's top hangs in tension); at most the bit MD. Throws as CaseAtDepth.
io::Case StiffCaseAtDepth(const io::Case& c, double bit_md, const analyses::RoadmapSettings& settings);

// `settings` with each default filled in from the case (analyses::RoadmapSettings), checked: InputError
// naming `analyses.roadmap.KEY` for a start beyond the bit MD or above where the string fits, or more
// than 2000 points.
analyses::RoadmapSettings CompleteRoadmapSettings(const io::Case& c, const analyses::RoadmapSettings& settings);
// The depths of a complete roadmap, top down, the case's bit MD the last.
std::vector<double> RoadmapDepths(const io::Case& c, const analyses::RoadmapSettings& settings);

struct RoadmapOptions {
  int jobs = 1;  // points at once (threads, each with its share of the cores)
  // After each point: the points done, failed, and the seconds left, estimated with a point's time
  // in proportion to its bit depth (the string's length).
  std::function<void(int done, int total, int failed, double seconds_left)> progress;
  // The solvers' progress, one line at a time, each prefixed with its depth and run (called from the
  // jobs' threads, one line at a time under a lock).
  std::function<void(const std::string&)> log;
};

// The stiff-string roadmap (settings complete: CompleteRoadmapSettings), depth by depth, each
// friction factor at each depth, in that order (settings.model is not read: RunSoftRoadmap is the
// soft string's).
std::vector<RoadmapPoint> RunRoadmap(const io::Case& c, const analyses::RoadmapSettings& settings,
                                     const RoadmapOptions& options = {});

// The same points by the soft-string model (analyses/soft_string.hpp: Johancsik), each depth's
// string continued to the surface as CaseAtDepth does; milliseconds for a whole roadmap.
std::vector<RoadmapPoint> RunSoftRoadmap(const io::Case& c, const analyses::RoadmapSettings& settings);

// "stiff", "soft" or "both".
const char* RoadmapModelName(analyses::RoadmapModel model);

// roadmap.csv (one row a depth and friction factor, the case's output units) and roadmap.json (the
// same with the settings), and report.html with the roadmap's plots when `report`. `points` are the
// settings' model's (the stiff string's for both); with both, `soft_points` go to roadmap-soft.csv and
// roadmap.json's `soft_points`, and the report draws them beside the stiff string's.
// With the rig's readings (`readings`: pipeline/readings_files.hpp ReadingsJson, `readings_csv` its
// ReadingsCsv), roadmap.json's `readings` and readings.csv, and the report draws them over the curves.
io::ResultFiles ComposeRoadmapFiles(const io::Case& c, const analyses::RoadmapSettings& settings,
                                    const std::vector<RoadmapPoint>& points, const std::string& directory,
                                    bool report, double run_seconds,
                                    const std::vector<RoadmapPoint>& soft_points = {},
                                    const nlohmann::json& readings = nullptr, const std::string& readings_csv = "");

}  // namespace drillflex::pipeline
