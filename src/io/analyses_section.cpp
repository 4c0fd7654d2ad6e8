// Reads `analyses:`: which analyses a plain `run` performs, with their settings.
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "io/case_sections.hpp"

namespace drillflex::io {
namespace {

using units::Quantity;

analyses::StaticSettings ReadStatic(const YamlView& node) {
  node.ExpectMap("the static analysis settings");
  node.AllowOnlyKeys({"method", "max_iterations", "mwd_at"});
  analyses::StaticSettings settings;
  settings.mwd_at = node.OptionalQuantity("mwd_at", Quantity::Length);
  if (settings.mwd_at && *settings.mwd_at < 0.0) node.Child("mwd_at").Fail("expected a distance from the bit of at least 0");
  if (const auto method = node.OptionalChild("method")) {
    const std::string name = method->AsString();
    if (name == "newton") settings.method = analyses::StaticMethod::StrategyChain;
    else if (name == "relaxation") settings.method = analyses::StaticMethod::DynamicRelaxation;
    else method->Fail(fmt::format("expected 'newton' or 'relaxation', got '{}'", name));
  }
  settings.max_iterations = node.IntegerOr("max_iterations", settings.max_iterations);
  if (settings.max_iterations < 1) node.Child("max_iterations").Fail("expected at least 1 iteration");
  return settings;
}

// `campbell: {from, to, step}` (rotary speeds; `from` may be 0).
analyses::SpeedRange ReadCampbell(const YamlView& node) {
  node.ExpectMap("a Campbell speed range {from, to, step}", false);
  node.AllowOnlyKeys({"from", "to", "step"});
  analyses::SpeedRange range;
  range.from = node.QuantityOr("from", Quantity::RotarySpeed, 0.0);
  range.to = node.Quantity("to", Quantity::RotarySpeed);
  if (range.from < 0.0) node.Child("from").Fail("expected a rotary speed of at least 0 rpm");
  if (!(range.to > range.from)) node.Child("to").Fail("expected a rotary speed above 'from'");
  range.step = node.OptionalPositive("step", Quantity::RotarySpeed).value_or((range.to - range.from) / 20.0);
  if ((range.to - range.from) / range.step > 1000.0) node.Child("step").Fail("more than 1000 speeds: use a larger step");
  return range;
}

analyses::ModesSettings ReadModes(const YamlView& node, const model::Operation& operation) {
  node.ExpectMap("the modes settings {count, kind, gyroscopic, campbell}");
  node.AllowOnlyKeys({"count", "kind", "gyroscopic", "campbell"});
  analyses::ModesSettings settings;
  settings.count = node.IntegerOr("count", settings.count);
  if (settings.count < 1 || settings.count > 1000) node.Child("count").Fail("expected between 1 and 1000 modes");
  if (const auto kind = node.OptionalChild("kind")) {
    const std::string name = kind->AsString();
    if (name == "all") settings.kind = analyses::ModeKind::All;
    else if (name == "lateral") settings.kind = analyses::ModeKind::Lateral;
    else if (name == "axial") settings.kind = analyses::ModeKind::Axial;
    else if (name == "torsional") settings.kind = analyses::ModeKind::Torsional;
    else kind->Fail(fmt::format("expected all, lateral, axial or torsional, got '{}'", name));
  }
  if (const auto gyro = node.OptionalChild("gyroscopic")) settings.gyroscopic = gyro->AsBool();
  settings.rotary_speed = operation.rotary_speed;
  const bool lateral = settings.kind == analyses::ModeKind::All || settings.kind == analyses::ModeKind::Lateral;
  if (settings.gyroscopic && !lateral) {
    node.Child("gyroscopic").Fail("the gyroscopic terms couple lateral motion only: use kind all or lateral");
  }
  if (const auto campbell = node.OptionalChild("campbell")) {
    if (!settings.gyroscopic) campbell->Fail("a Campbell diagram needs 'gyroscopic: true'");
    settings.campbell = ReadCampbell(*campbell);
  }
  return settings;
}

analyses::Excitation ReadExcitation(const YamlView& item) {
  item.ExpectMap("an excitation {type, ...}", false);
  analyses::Excitation excitation;
  excitation.source_line = item.location().line;
  const std::string type = item.Child("type").AsString();
  if (type == "imbalance") {
    item.AllowOnlyKeys({"type", "at", "me"});
    excitation.type = analyses::ExcitationType::Imbalance;
    excitation.at = item.Quantity("at", Quantity::Length);
    excitation.imbalance = item.Positive("me", Quantity::Imbalance);
  } else if (type == "bit") {
    item.AllowOnlyKeys({"type", "harmonic", "lateral", "axial", "torsional"});
    excitation.type = analyses::ExcitationType::Bit;
    excitation.harmonic = item.IntegerOr("harmonic", 1);
    excitation.lateral = item.QuantityOr("lateral", Quantity::Force, 0.0);
    excitation.axial = item.QuantityOr("axial", Quantity::Force, 0.0);
    excitation.torsional = item.QuantityOr("torsional", Quantity::Moment, 0.0);
    if (excitation.harmonic < 1) item.Child("harmonic").Fail("expected a harmonic of at least 1");
  } else if (type == "motor") {
    item.AllowOnlyKeys({"type", "lobes", "lateral", "at", "speed"});
    excitation.type = analyses::ExcitationType::Motor;
    excitation.lobes = item.IntegerOr("lobes", 0);
    excitation.lateral = item.Positive("lateral", Quantity::Force);
    excitation.at = item.QuantityOr("at", Quantity::Length, -1.0);
    excitation.motor_speed = item.OptionalPositive("speed", Quantity::RotarySpeed);
    if (item.Has("lobes") && excitation.lobes < 1) item.Child("lobes").Fail("expected at least 1 lobe");
  } else {
    item.Child("type").Fail(fmt::format("unknown excitation type '{}'; expected imbalance, bit or motor", type));
  }
  return excitation;
}

analyses::VibrationSettings ReadVibration(const YamlView& node) {
  node.ExpectMap("the vibration settings {rpm, excitations}");
  node.AllowOnlyKeys({"rpm", "excitations", "clearance_fraction", "stress_limit", "method", "basis"});
  analyses::VibrationSettings settings;
  if (const auto method = node.OptionalChild("method")) {
    const std::string name = method->AsString();
    if (name == "reduced") settings.method = analyses::VibrationMethod::Reduced;
    else if (name == "direct") settings.method = analyses::VibrationMethod::Direct;
    else method->Fail(fmt::format("expected 'reduced' or 'direct', got '{}'", name));
  }
  if (const auto basis = node.OptionalChild("basis")) {
    basis->ExpectMap("the reduced basis {shifts, depth}", false);
    basis->AllowOnlyKeys({"shifts", "depth"});
    settings.basis_shifts = basis->IntegerOr("shifts", settings.basis_shifts);
    settings.basis_depth = basis->IntegerOr("depth", settings.basis_depth);
    if (settings.basis_shifts < 1 || settings.basis_shifts > 1000) basis->Child("shifts").Fail("expected 1 to 1000 shifts");
    if (settings.basis_depth < 1 || settings.basis_depth > 20) basis->Child("depth").Fail("expected a depth of 1 to 20");
  }
  if (const auto rpm = node.OptionalChild("rpm")) {
    rpm->ExpectMap("an RPM sweep {from, to, step}", false);
    rpm->AllowOnlyKeys({"from", "to", "step"});
    settings.speed_from = rpm->QuantityOr("from", Quantity::RotarySpeed, settings.speed_from);
    settings.speed_to = rpm->QuantityOr("to", Quantity::RotarySpeed, settings.speed_to);
    settings.speed_step = rpm->OptionalPositive("step", Quantity::RotarySpeed).value_or(settings.speed_step);
    if (settings.speed_from <= 0.0) rpm->Child("from").Fail("the sweep must start above 0 rpm");
    if (!(settings.speed_to >= settings.speed_from)) rpm->Fail("'to' must not lie below 'from'");
    if ((settings.speed_to - settings.speed_from) / settings.speed_step > 1.0e5) rpm->Fail("more than 100000 RPM values: use a larger step");
  }
  settings.clearance_fraction =
      node.OptionalPositive("clearance_fraction", Quantity::Dimensionless).value_or(settings.clearance_fraction);
  settings.stress_limit = node.OptionalPositive("stress_limit", Quantity::Stress).value_or(settings.stress_limit);
  if (const auto list = node.OptionalChild("excitations")) {
    list->ExpectSequence("excitations");
    for (std::size_t i = 0; i < list->size(); ++i) settings.excitations.push_back(ReadExcitation(list->Item(i)));
  }
  return settings;
}

analyses::TransientSettings ReadTransient(const YamlView& node, const model::Operation& operation) {
  node.ExpectMap("the transient settings {duration, output_interval, probes}");
  node.AllowOnlyKeys({"duration", "output_interval", "probes", "time_step", "rho_infinity", "tolerance", "start",
                      "initial_loads", "top_drive", "block", "bit_rock", "excitations", "vtk_frames",
                      "fluid_frequency"});
  analyses::TransientSettings settings;
  settings.duration = node.OptionalPositive("duration", Quantity::Time).value_or(settings.duration);
  settings.output_interval = node.OptionalPositive("output_interval", Quantity::Time).value_or(settings.output_interval);
  if (settings.duration / settings.output_interval > 1e7) {
    node.Fail("more than 10 million output samples: use a larger output_interval");
  }
  settings.time_step = node.OptionalPositive("time_step", Quantity::Time);
  // Hz in the case, ω = 2π f inside (the annulus fluid's C_m and C_v; TransientFluidFrequency).
  if (const auto f = node.OptionalPositive("fluid_frequency", Quantity::Frequency)) settings.fluid_frequency = 2.0 * kPi * *f;
  // The frames of transient.pvd (io/vtk_files.hpp): string_0000.vtp to string_9999.vtp at the most.
  if (const auto frames = node.OptionalChild("vtk_frames")) {
    settings.vtk_frames = frames->AsInteger();
    if (*settings.vtk_frames < 0 || *settings.vtk_frames > 10000) {
      frames->Fail("expected between 0 and 10000 frames (0: no transient.pvd)");
    }
  }
  settings.rho_infinity = node.QuantityOr("rho_infinity", Quantity::Dimensionless, settings.rho_infinity);
  if (!(settings.rho_infinity >= 0.0 && settings.rho_infinity <= 1.0)) {
    node.Child("rho_infinity").Fail("expected a spectral radius between 0 and 1 (1: no numerical damping)");
  }
  settings.tolerance = node.OptionalPositive("tolerance", Quantity::Dimensionless).value_or(settings.tolerance);
  if (settings.tolerance >= 0.1) node.Child("tolerance").Fail("expected a relative tolerance below 0.1");
  if (const auto start = node.OptionalChild("start")) {
    const std::string name = start->AsString();
    if (name == "equilibrium") settings.start = analyses::TransientStart::Equilibrium;
    else if (name == "reference") settings.start = analyses::TransientStart::Reference;
    else start->Fail(fmt::format("expected 'equilibrium' or 'reference', got '{}'", name));
  }
  if (const auto loads = node.OptionalChild("initial_loads")) {
    settings.initial_loads = ReadLoadsSection(*loads);
    if (settings.start == analyses::TransientStart::Reference && !settings.initial_loads.empty()) {
      loads->Fail("initial loads need the start from the equilibrium (start: equilibrium), not the reference");
    }
  }
  // The vibration analysis's imbalance items; a bit's or a motor's harmonic force has no meaning in
  // the time domain (the bit-rock law and the string's own rotation make those).
  if (const auto list = node.OptionalChild("excitations")) {
    list->ExpectSequence("excitations");
    for (std::size_t i = 0; i < list->size(); ++i) {
      const YamlView item = list->Item(i);
      const analyses::Excitation excitation = ReadExcitation(item);
      if (excitation.type != analyses::ExcitationType::Imbalance) {
        item.Child("type").Fail("a transient takes imbalance excitations only (the bit-rock law makes the bit's)");
      }
      settings.imbalances.push_back(model::Imbalance{excitation.at, excitation.imbalance});
    }
  }
  if (const auto bit_rock = node.OptionalChild("bit_rock")) settings.bit_rock = ReadBitRockSection(*bit_rock);
  // A rotating operation turns the top in a transient too (model/drives.hpp, io/drives_section.cpp).
  if (const auto drive = node.PresentChild("top_drive")) {
    settings.top_drive = ReadTopDrive(*drive, operation);
  } else if (operation.rotary_speed != 0.0) {
    settings.top_drive = model::TopDrive{model::TopDriveMode::Speed, {operation.rotary_speed, model::kDefaultTopDriveRamp}};
  }
  if (const auto block = node.PresentChild("block")) settings.block = ReadBlock(*block, operation);
  if (const auto probes = node.OptionalChild("probes")) {
    probes->ExpectSequence("probe distances from the bit");
    for (std::size_t i = 0; i < probes->size(); ++i) {
      settings.probes.push_back(probes->Item(i).AsQuantity(Quantity::Length));
    }
  }
  return settings;
}

// `roadmap: {from, step, friction, cased_friction, rpm, trip_speed, model, stiff_length}`: the settings of
// `drillflex roadmap`.
analyses::RoadmapSettings ReadRoadmap(const YamlView& node) {
  node.ExpectMap("the roadmap settings {from, step, friction, cased_friction, rpm, trip_speed, model, stiff_length}");
  node.AllowOnlyKeys({"from", "step", "friction", "cased_friction", "rpm", "trip_speed", "model", "stiff_length"});
  analyses::RoadmapSettings settings;
  settings.from_md = node.OptionalPositive("from", Quantity::Length).value_or(0.0);
  settings.step = node.OptionalPositive("step", Quantity::Length).value_or(0.0);
  if (const auto friction = node.OptionalChild("friction")) {
    friction->ExpectSequence("a list of friction factors [0.2, 0.3, ...]");
    if (friction->size() == 0 || friction->size() > 20) friction->Fail("expected 1 to 20 friction factors");
    for (std::size_t i = 0; i < friction->size(); ++i) {
      const double factor = friction->Item(i).AsQuantity(Quantity::Dimensionless);
      if (!(factor >= 0.0 && factor <= 2.0)) friction->Item(i).Fail("expected a friction factor from 0 to 2");
      settings.friction.push_back(factor);
    }
  }
  if (const auto cased = node.OptionalChild("cased_friction")) {
    const double factor = cased->AsQuantity(Quantity::Dimensionless);
    if (!(factor >= 0.0 && factor <= 2.0)) cased->Fail("expected a friction factor from 0 to 2");
    settings.cased_friction = factor;
  }
  settings.rotary_speed = node.OptionalPositive("rpm", Quantity::RotarySpeed).value_or(0.0);
  settings.trip_speed = node.OptionalPositive("trip_speed", Quantity::Velocity).value_or(settings.trip_speed);
  if (const auto model = node.OptionalChild("model")) {
    const std::string name = model->AsString();
    if (name == "stiff") settings.model = analyses::RoadmapModel::Stiff;
    else if (name == "soft") settings.model = analyses::RoadmapModel::Soft;
    else if (name == "both") settings.model = analyses::RoadmapModel::Both;
    else model->Fail(fmt::format("expected 'stiff', 'soft' or 'both', got '{}'", name));
  }
  if (const auto stiff = node.OptionalChild("stiff_length")) {
    if (stiff->IsScalar() && stiff->AsString() == "surface") {
      settings.stiff_length = std::numeric_limits<double>::infinity();
    } else {
      const double length = stiff->AsQuantity(Quantity::Length);
      if (!(length > 0.0 && std::isfinite(length))) {
        stiff->Fail("expected a positive length of string from the bit, or 'surface'");
      }
      settings.stiff_length = length;
    }
  }
  return settings;
}

// `rss: {type: push, at, force, toolface, steer}` (push-the-bit) or `{type: point, at, offset, toolface,
// steer}` (point-the-bit).
analyses::RssSettings ReadRss(const YamlView& node) {
  node.ExpectMap("a rotary steerable system {type: push, at, force, toolface, steer} or {type: point, at, offset, "
                 "toolface, steer}",
                 false);
  node.AllowOnlyKeys({"type", "at", "force", "offset", "toolface", "steer"});
  analyses::RssSettings rss;
  rss.source_line = node.location().line;
  const std::string type = node.Child("type").AsString();
  if (type == "push") {
    rss.type = analyses::RssType::Push;
    if (node.Has("offset")) {
      node.Child("offset").Fail("a push-the-bit system pushes with its pads' `force`; `offset` (the bit's tilt) is a "
                                "point-the-bit system's (type: point)");
    }
    rss.force = node.Positive("force", Quantity::Force);
  } else if (type == "point") {
    rss.type = analyses::RssType::Point;
    if (node.Has("force")) {
      node.Child("force").Fail("a point-the-bit system tilts the bit by its `offset`; `force` (the pads') is a "
                               "push-the-bit system's (type: push)");
    }
    rss.offset = node.Quantity("offset", Quantity::Angle);
    if (!(rss.offset >= 0.0 && rss.offset <= analyses::kMaxRssOffset)) {
      node.Child("offset").Fail("expected the bit's offset angle against the tool's axis between 0 and 3 deg (the "
                                "tools' are 0.2-1.2 deg)");
    }
  } else {
    node.Child("type").Fail(fmt::format("expected push (push-the-bit: pads) or point (point-the-bit: the bit's shaft "
                                        "tilted), got '{}'",
                                        type));
  }
  rss.at = node.Positive("at", Quantity::Length);
  rss.toolface = node.QuantityOr("toolface", Quantity::Angle, 0.0);
  if (rss.toolface < 0.0 || rss.toolface > 2.0 * kPi) {
    node.Child("toolface").Fail("expected a toolface between 0 and 360 deg (0 the high side, 90 the right)");
  }
  rss.steer = node.QuantityOr("steer", Quantity::Dimensionless, 1.0);
  if (!(rss.steer >= 0.0 && rss.steer <= 1.0)) {
    node.Child("steer").Fail("expected the steering ratio, the fraction of the time the system steers: 0 to 1");
  }
  return rss;
}

// `formation: {anisotropy, dip, dip_azimuth}`.
analyses::FormationSettings ReadFormation(const YamlView& node) {
  node.ExpectMap("the formation's anisotropy {anisotropy, dip, dip_azimuth}", false);
  node.AllowOnlyKeys({"anisotropy", "dip", "dip_azimuth"});
  analyses::FormationSettings formation;
  formation.anisotropy = node.Quantity("anisotropy", Quantity::Dimensionless);
  if (!(formation.anisotropy > -1.0 && formation.anisotropy < 1.0)) {
    node.Child("anisotropy").Fail("expected the formation's anisotropy index, between -1 and 1 (0: isotropic)");
  }
  formation.dip = node.QuantityOr("dip", Quantity::Angle, 0.0);
  if (formation.dip < 0.0 || formation.dip > 0.5 * kPi) node.Child("dip").Fail("expected a dip between 0 and 90 deg");
  formation.dip_azimuth = node.QuantityOr("dip_azimuth", Quantity::Angle, 0.0);
  if (formation.dip_azimuth < 0.0 || formation.dip_azimuth > 2.0 * kPi) {
    node.Child("dip_azimuth").Fail("expected the azimuth the beds dip toward, between 0 and 360 deg");
  }
  return formation;
}

}  // namespace

analyses::AnalysesConfig ReadAnalysesSection(const YamlView& node, const model::Operation& operation) {
  node.ExpectMap("the analyses to run (static, modes, vibration, buckling, transient, roadmap, tendency)");
  node.AllowOnlyKeys({"static", "modes", "vibration", "buckling", "transient", "roadmap", "tendency"});
  analyses::AnalysesConfig config;
  // A key that is present runs its analysis, even with empty settings (`static: {}` or `static:`).
  if (const auto item = node.PresentChild("static")) config.static_analysis = ReadStatic(*item);
  if (const auto item = node.PresentChild("modes")) config.modes = ReadModes(*item, operation);
  if (const auto item = node.PresentChild("vibration")) config.vibration = ReadVibration(*item);
  if (const auto item = node.PresentChild("buckling")) {
    item->ExpectMap("the buckling settings");
    item->AllowOnlyKeys({"modes", "scale"});
    config.buckling = analyses::BucklingSettings{};
    config.buckling->modes = item->IntegerOr("modes", 1);
    if (config.buckling->modes < 1) item->Child("modes").Fail("expected at least 1 buckling mode");
    // Which loads the multiplier scales: the WOB alone, or every load (default: the WOB if there is one).
    if (const auto scale = item->OptionalChild("scale")) {
      const std::string name = scale->AsString();
      if (name == "wob") {
        if (operation.weight_on_bit == 0.0 && !operation.hook_load) {
          scale->Fail("`wob` scales the weight on bit, and the case has none (operation.wob or operation.hook_load)");
        }
        config.buckling->scale = analyses::BucklingScale::Wob;
      } else if (name == "all") {
        config.buckling->scale = analyses::BucklingScale::AllLoads;
      } else {
        scale->Fail(fmt::format("expected wob or all, got '{}'", name));
      }
    }
  }
  if (const auto item = node.PresentChild("transient")) config.transient = ReadTransient(*item, operation);
  if (const auto item = node.PresentChild("roadmap")) config.roadmap = ReadRoadmap(*item);
  if (const auto item = node.PresentChild("tendency")) {
    item->ExpectMap("the tendency settings");
    item->AllowOnlyKeys({"steerability", "sensitivities", "rss", "formation"});
    config.tendency = analyses::TendencySettings{};
    if (const auto sensitivities = item->OptionalChild("sensitivities")) {
      config.tendency->sensitivities = sensitivities->AsBool();
    }
    if (const auto rss = item->OptionalChild("rss")) config.tendency->rss = ReadRss(*rss);
    if (const auto formation = item->OptionalChild("formation")) config.tendency->formation = ReadFormation(*formation);
    if (const auto steerability = item->OptionalChild("steerability")) {
      config.tendency->steerability = steerability->AsQuantity(units::Quantity::Dimensionless);
      if (!(config.tendency->steerability >= 0.0)) {
        steerability->Fail("expected the bit's steerability, a number >= 0 (its lateral over its axial drillability; "
                           "1e6 for the zero-side-force criterion)");
      }
    }
  }
  return config;
}

}  // namespace drillflex::io
