// Quantities with units at the edge of the engine. Inside, everything is SI (m, kg, s, N, Pa, rad).
//
// A case file gives a bare number in the unit its `units:` system assigns to that quantity
// (field: ft for depths, in for diameters, klbf for WOB, ...), or a string with its own unit
// ("8.5 in", "12.5 ppg", "15000 ft*lbf"). A unit of the wrong dimension is an error that names
// both the unit's kind and the kind expected.
#pragma once

#include <string>
#include <string_view>

namespace drillflex::units {

// The unit system of a case's bare numbers and of the results it writes.
enum class System { SI, Field };

// Physical dimension as exponents of length, mass, time and plane angle. Angle is kept as its own
// base dimension so that rpm (angle/time) and Hz, or deg/100ft and 1/m, are told apart.
struct Dimension {
  int length = 0;
  int mass = 0;
  int time = 0;
  int angle = 0;
  friend bool operator==(const Dimension&, const Dimension&) = default;
};

// What a number means. Each quantity has a dimension and a default unit in each system.
enum class Quantity {
  Dimensionless,      // ratios, factors, counts
  Length,             // depths, MD, component lengths, positions: m | ft
  Diameter,           // OD, ID, hole and blade diameters, clearances: m | in
  Force,              // N | lbf
  WeightOnBit,        // N | klbf
  Moment,             // torque and bending moment: N*m | ft*lbf
  Density,            // kg/m3 | ppg
  Viscosity,          // Pa*s | cP
  Stress,             // moduli, stresses, pressures: Pa | psi
  Angle,              // deg | deg
  RotarySpeed,        // rpm | rpm
  Time,               // s | s
  Mass,               // kg | lb
  MassPerLength,      // nominal pipe weight: kg/m | lb/ft
  ForcePerLength,     // distributed loads, buoyed weight: N/m | lbf/ft
  DoglegSeverity,     // deg/30m | deg/100ft
  Imbalance,          // mass times eccentricity: kg*m | lb*in
  Stiffness,          // contact and spring stiffness: N/m | lbf/in
  RotationalStiffness,// N*m/rad | ft*lbf/rad
  Velocity,           // m/s | ft/s
  Acceleration,       // gravity: m/s2 | m/s2 (always m/s² by the case contract)
  Frequency,          // Hz | Hz
  FlowRate,           // m3/s | gpm
  RevolutionsPerVolume, // mud motor speed per flow: rev/m3 | rev/gal (stored as rad/m3)
  WearFactor,         // casing wear factor, volume per friction work: 1/Pa | 1/psi (1e-10 1/psi = 1e-10 in²/lbf)
};

// The dimension of a quantity.
Dimension DimensionOf(Quantity quantity);

// A readable name for error messages: "a diameter (length)", "a density", ...
std::string QuantityName(Quantity quantity);

// A readable name of a dimension: "a length", "a force", "a density", ..., else the exponent form
// "a quantity in m^a kg^b s^c rad^d" (zero powers left out).
std::string DimensionName(const Dimension& dimension);

// The default unit symbol of a quantity in a system, e.g. (Diameter, Field) -> "in".
std::string_view DefaultUnit(Quantity quantity, System system);

// A parsed unit expression: multiply a value in it by to_si to get SI.
struct Unit {
  double to_si = 1.0;
  Dimension dimension;
};

// Parses a unit expression: symbols (m, mm, in, ft, N, kN, lbf, klbf, ppg, sg, psi, ksi, cP, rpm,
// deg, ...), products with '*', '·' or a space, one '/', exponents (m3, m^3, m³) and numeric
// factors in the denominator ("deg/100ft", "°/30 m"). An empty expression is dimensionless 1.
// Throws UnitError on an unknown symbol (naming close known ones) or a malformed expression.
Unit ParseUnit(std::string_view expression);

// SI value of a bare number given in the system's default unit for the quantity.
double ToSI(double value, Quantity quantity, System system);

// The value in the system's default unit of an SI value. (Not named si_value: glibc's <signal.h>
// defines si_value as a macro.)
double FromSI(double value_in_si, Quantity quantity, System system);

// Converts between any two units of the same dimension; throws UnitError otherwise.
double Convert(double value, std::string_view from_unit, std::string_view to_unit);

// Reads "8.5 in", "30e6 psi", "8-1/2 in" (a mixed fraction), or a bare number (then the system's
// default unit for the quantity), and returns SI. Throws UnitError naming the unit's kind and the
// quantity expected when the dimension is wrong, or when the text is not a number with a unit.
double ParseQuantity(std::string_view text, Quantity quantity, System system);

// Parses "SI" / "field" (case-insensitive); throws UnitError otherwise.
System ParseSystem(std::string_view text);
std::string_view SystemName(System system);

}  // namespace drillflex::units
