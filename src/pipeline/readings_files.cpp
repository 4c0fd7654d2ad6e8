#include "pipeline/readings_files.hpp"

#include <cmath>
#include <optional>

#include "io/result_files.hpp"

namespace drillflex::pipeline {
namespace {

using units::Quantity;

nlohmann::json Number(double value) { return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(nullptr); }

std::string Cell(double value) { return std::isfinite(value) ? io::CsvTable::Number(value) : ""; }

double TorqueOf(const io::RigReading& reading) {
  return reading.surface_torque ? *reading.surface_torque : std::numeric_limits<double>::quiet_NaN();
}

std::string UnitOf(Quantity quantity, units::System system) {
  return quantity == Quantity::Dimensionless ? "-" : std::string(units::DefaultUnit(quantity, system));
}

}  // namespace

nlohmann::json ReadingsJson(const io::Case& c, const io::RigReadings& readings,
                            const std::vector<ModelledReadings>& models) {
  const units::System system = c.output_units;
  auto out = [system](double si, Quantity quantity) { return units::FromSI(si, quantity, system); };
  nlohmann::json json = nlohmann::json::object();
  json["file"] = readings.file;
  json["units"] = {{"bit_md", UnitOf(Quantity::Length, system)},
                   {"hook_load", UnitOf(Quantity::Force, system)},
                   {"surface_torque", UnitOf(Quantity::Moment, system)},
                   {"wob", UnitOf(Quantity::WeightOnBit, system)},
                   {"rpm", UnitOf(Quantity::RotarySpeed, system)}};
  nlohmann::json md = nlohmann::json::array(), activity = nlohmann::json::array(), hook = nlohmann::json::array(),
                 torque = nlohmann::json::array(), wob = nlohmann::json::array(), rpm = nlohmann::json::array(),
                 line = nlohmann::json::array();
  for (const io::RigReading& r : readings.rows) {
    md.push_back(out(r.bit_md, Quantity::Length));
    activity.push_back(io::RigActivityName(r.activity));
    hook.push_back(out(r.hook_load, Quantity::Force));
    torque.push_back(Number(out(TorqueOf(r), Quantity::Moment)));
    wob.push_back(out(r.weight_on_bit, Quantity::WeightOnBit));
    rpm.push_back(out(r.rotary_speed, Quantity::RotarySpeed));
    line.push_back(r.line);
  }
  json["bit_md"] = std::move(md);
  json["activity"] = std::move(activity);
  json["hook_load"] = std::move(hook);
  json["surface_torque"] = std::move(torque);
  json["wob"] = std::move(wob);
  json["rpm"] = std::move(rpm);
  json["line"] = std::move(line);
  json["warnings"] = readings.warnings;
  nlohmann::json list = nlohmann::json::array();
  for (const ModelledReadings& model : models) {
    nlohmann::json m = {{"label", model.label}, {"friction", model.open_hole_friction}};
    nlohmann::json h = nlohmann::json::array(), t = nlohmann::json::array(), hr = nlohmann::json::array(),
                   tr = nlohmann::json::array(), message = nlohmann::json::array();
    for (std::size_t i = 0; i < readings.rows.size(); ++i) {
      const io::RigReading& r = readings.rows[i];
      const ModelledReading& x = model.modelled[i];
      h.push_back(Number(out(x.hook_load, Quantity::Force)));
      t.push_back(Number(out(x.surface_torque, Quantity::Moment)));
      hr.push_back(Number(out(x.hook_load - r.hook_load, Quantity::Force)));
      tr.push_back(Number(out(x.surface_torque - TorqueOf(r), Quantity::Moment)));
      message.push_back(x.message);
    }
    m["hook_load"] = std::move(h);
    m["surface_torque"] = std::move(t);
    m["hook_load_residual"] = std::move(hr);
    m["torque_residual"] = std::move(tr);
    m["message"] = std::move(message);
    list.push_back(std::move(m));
  }
  json["models"] = std::move(list);
  return json;
}

std::string ReadingsCsv(const io::Case& c, const io::RigReadings& readings, const std::vector<ModelledReadings>& models) {
  const units::System system = c.output_units;
  auto out = [system](double si, Quantity quantity) { return units::FromSI(si, quantity, system); };
  const std::string force = UnitOf(Quantity::Force, system), moment = UnitOf(Quantity::Moment, system);
  io::CsvTable table({"bit_md", "activity", "model", "friction", "hook_load", "modelled_hook_load", "hook_load_residual",
                      "surface_torque", "modelled_surface_torque", "torque_residual", "wob", "rpm", "line", "message"},
                     {UnitOf(Quantity::Length, system), "-", "-", "-", force, force, force, moment, moment, moment,
                      UnitOf(Quantity::WeightOnBit, system), UnitOf(Quantity::RotarySpeed, system), "-", "-"});
  for (const ModelledReadings& model : models) {
    for (std::size_t i = 0; i < readings.rows.size(); ++i) {
      const io::RigReading& r = readings.rows[i];
      const ModelledReading& x = model.modelled[i];
      table.AddCells({Cell(out(r.bit_md, Quantity::Length)), io::CsvTable::Text(io::RigActivityName(r.activity)),
                      io::CsvTable::Text(model.label), Cell(model.open_hole_friction),
                      Cell(out(r.hook_load, Quantity::Force)), Cell(out(x.hook_load, Quantity::Force)),
                      Cell(out(x.hook_load - r.hook_load, Quantity::Force)), Cell(out(TorqueOf(r), Quantity::Moment)),
                      Cell(out(x.surface_torque, Quantity::Moment)),
                      Cell(out(x.surface_torque - TorqueOf(r), Quantity::Moment)),
                      Cell(out(r.weight_on_bit, Quantity::WeightOnBit)), Cell(out(r.rotary_speed, Quantity::RotarySpeed)),
                      std::to_string(r.line), io::CsvTable::Text(x.message)});
    }
  }
  return table.ToString();
}

}  // namespace drillflex::pipeline
