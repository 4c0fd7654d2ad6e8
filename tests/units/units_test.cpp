// Tests of the units layer: every supported unit against an exact factor written out here from
// its definition (NIST SP 811 appendix B; decimal expansions computed with 30-digit arithmetic,
// not by this code), round trips of every quantity in both systems, the reading of values with
// and without units, mixed fractions, and every error path with its message.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "units/unit_table.hpp"
#include "units/units.hpp"

namespace drillflex::units {
namespace units_test {

using ::testing::HasSubstr;

constexpr double kRelativeTolerance = 1e-9;

// Dimensions written out, independent of the code's tables.
constexpr Dimension kDimensionless{0, 0, 0, 0};
constexpr Dimension kLength{1, 0, 0, 0};
constexpr Dimension kMass{0, 1, 0, 0};
constexpr Dimension kTime{0, 0, 1, 0};
constexpr Dimension kAngle{0, 0, 0, 1};
constexpr Dimension kForce{1, 1, -2, 0};
constexpr Dimension kMoment{2, 1, -2, 0};
constexpr Dimension kDensity{-3, 1, 0, 0};
constexpr Dimension kPressure{-1, 1, -2, 0};
constexpr Dimension kViscosity{-1, 1, -1, 0};
constexpr Dimension kRotarySpeed{0, 0, -1, 1};
constexpr Dimension kFrequency{0, 0, -1, 0};
constexpr Dimension kMassPerLength{-1, 1, 0, 0};
constexpr Dimension kForcePerLength{0, 1, -2, 0};
constexpr Dimension kDogleg{-1, 0, 0, 1};
constexpr Dimension kImbalance{1, 1, 0, 0};
constexpr Dimension kVelocity{1, 0, -1, 0};
constexpr Dimension kAcceleration{1, 0, -2, 0};
constexpr Dimension kFlowRate{3, 0, -1, 0};
constexpr Dimension kRevolutionsPerVolume{-3, 0, 0, 1};
constexpr Dimension kRotationalStiffness{2, 1, -2, -1};

// Exact values (30-digit decimal arithmetic from the defining constants, rounded to 17 digits).
constexpr double kPoundPerGallon = 119.82642731689663;    // 0.45359237 / 3.785411784e-3 kg/m³
constexpr double kFootPoundForce = 1.3558179483314004;    // 4.4482216152605 x 0.3048 N·m
constexpr double kPsi = 6894.7572931683613;               // 4.4482216152605 / 0.0254² Pa
constexpr double kPoundPerCubicFoot = 16.018463373960140; // 0.45359237 / 0.3048³ kg/m³
constexpr double kPoundPerFoot = 1.4881639435695538;      // 0.45359237 / 0.3048 kg/m
constexpr double kPoundForcePerFoot = 14.593902937206365; // N/m
constexpr double kPoundForcePerInch = 175.12683524647638; // N/m
constexpr double kDegree = 0.017453292519943296;          // π/180 rad
constexpr double kRevolution = 6.2831853071795865;        // 2π rad
constexpr double kRpm = 0.10471975511965977;              // 2π/60 rad/s
constexpr double kDegreePer30m = 5.8177641733144319e-4;   // (π/180)/30 rad/m
constexpr double kDegreePer100ft = 5.7261458398764094e-4; // (π/180)/30.48 rad/m
constexpr double kGallonPerMinute = 6.30901964e-5;        // 3.785411784e-3 / 60 m³/s
constexpr double kBarrelPerMinute = 2.6497882488e-3;      // 42 x 3.785411784e-3 / 60 m³/s
constexpr double kPoundInch = 0.011521246198;             // 0.45359237 x 0.0254 kg·m
constexpr double kOunceInch = 7.2007788737500e-4;         // 0.45359237/16 x 0.0254 kg·m
constexpr double kRevPerGallon = 1659.8419579441946;      // 2π / 3.785411784e-3 rad/m³

void ExpectRelativelyNear(double actual, double expected, double tolerance = kRelativeTolerance) {
  EXPECT_LE(std::abs(actual - expected), tolerance * std::abs(expected))
      << "actual " << actual << ", expected " << expected;
}

struct Conversion {
  const char* unit;
  double to_si;         // one of `unit` in SI
  Dimension dimension;  // of `unit`
  const char* si_unit;  // the SI unit of that dimension, for Convert in both directions
};

const std::vector<Conversion>& AllConversions() {
  static const std::vector<Conversion> conversions{
      {"m", 1.0, kLength, "m"}, {"mm", 1e-3, kLength, "m"}, {"cm", 1e-2, kLength, "m"},
      {"km", 1e3, kLength, "m"}, {"in", 0.0254, kLength, "m"}, {"ft", 0.3048, kLength, "m"},
      {"N", 1.0, kForce, "N"}, {"kN", 1e3, kForce, "N"}, {"lbf", 4.4482216152605, kForce, "N"},
      {"klbf", 4448.2216152605, kForce, "N"},
      {"N*m", 1.0, kMoment, "N*m"}, {"kN*m", 1e3, kMoment, "N*m"},
      {"ft*lbf", kFootPoundForce, kMoment, "N*m"}, {"lbf*ft", kFootPoundForce, kMoment, "N*m"},
      {"kft*lbf", 1e3 * kFootPoundForce, kMoment, "N*m"},
      {"kg/m3", 1.0, kDensity, "kg/m3"}, {"kg/m^3", 1.0, kDensity, "kg/m3"},
      {"kg/m\u00B3", 1.0, kDensity, "kg/m3"}, {"g/cm3", 1000.0, kDensity, "kg/m3"},
      {"ppg", kPoundPerGallon, kDensity, "kg/m3"}, {"sg", 1000.0, kDensity, "kg/m3"},
      {"lb/ft3", kPoundPerCubicFoot, kDensity, "kg/m3"},
      {"Pa", 1.0, kPressure, "Pa"}, {"kPa", 1e3, kPressure, "Pa"}, {"MPa", 1e6, kPressure, "Pa"},
      {"GPa", 1e9, kPressure, "Pa"}, {"bar", 1e5, kPressure, "Pa"}, {"psi", kPsi, kPressure, "Pa"},
      {"ksi", 1e3 * kPsi, kPressure, "Pa"},
      {"Pa*s", 1.0, kViscosity, "Pa*s"}, {"mPa*s", 1e-3, kViscosity, "Pa*s"},
      {"cP", 1e-3, kViscosity, "Pa*s"}, {"P", 0.1, kViscosity, "Pa*s"},
      {"deg", kDegree, kAngle, "rad"}, {"\u00B0", kDegree, kAngle, "rad"},
      {"rad", 1.0, kAngle, "rad"}, {"rev", kRevolution, kAngle, "rad"},
      {"rpm", kRpm, kRotarySpeed, "rad/s"}, {"rad/s", 1.0, kRotarySpeed, "rad/s"},
      {"rps", kRevolution, kRotarySpeed, "rad/s"},
      {"Hz", 1.0, kFrequency, "1/s"},
      {"kg/m", 1.0, kMassPerLength, "kg/m"}, {"lb/ft", kPoundPerFoot, kMassPerLength, "kg/m"},
      {"N/m", 1.0, kForcePerLength, "N/m"}, {"lbf/ft", kPoundForcePerFoot, kForcePerLength, "N/m"},
      {"lbf/in", kPoundForcePerInch, kForcePerLength, "N/m"}, {"kN/m", 1e3, kForcePerLength, "N/m"},
      {"deg/30m", kDegreePer30m, kDogleg, "rad/m"}, {"deg/100ft", kDegreePer100ft, kDogleg, "rad/m"},
      {"\u00B0/30 m", kDegreePer30m, kDogleg, "rad/m"},
      {"\u00B0/100 ft", kDegreePer100ft, kDogleg, "rad/m"},
      {"kg*m", 1.0, kImbalance, "kg*m"}, {"g*mm", 1e-6, kImbalance, "kg*m"},
      {"lb*in", kPoundInch, kImbalance, "kg*m"}, {"oz*in", kOunceInch, kImbalance, "kg*m"},
      {"s", 1.0, kTime, "s"}, {"ms", 1e-3, kTime, "s"}, {"min", 60.0, kTime, "s"},
      {"h", 3600.0, kTime, "s"},
      {"kg", 1.0, kMass, "kg"}, {"g", 1e-3, kMass, "kg"}, {"t", 1e3, kMass, "kg"},
      {"lb", 0.45359237, kMass, "kg"},
      {"m/s", 1.0, kVelocity, "m/s"}, {"ft/s", 0.3048, kVelocity, "m/s"},
      {"ft/min", 0.00508, kVelocity, "m/s"}, {"m/min", 1.0 / 60.0, kVelocity, "m/s"},
      {"ft/h", 0.3048 / 3600.0, kVelocity, "m/s"}, {"m/h", 1.0 / 3600.0, kVelocity, "m/s"},
      {"m/s2", 1.0, kAcceleration, "m/s2"}, {"ft/s2", 0.3048, kAcceleration, "m/s2"},
      {"m3/s", 1.0, kFlowRate, "m3/s"}, {"L/min", 1e-3 / 60.0, kFlowRate, "m3/s"},
      {"gpm", kGallonPerMinute, kFlowRate, "m3/s"}, {"bbl/min", kBarrelPerMinute, kFlowRate, "m3/s"},
      {"rev/gal", kRevPerGallon, kRevolutionsPerVolume, "rad/m3"},
      {"rev/L", 1000.0 * kRevolution, kRevolutionsPerVolume, "rad/m3"},
      {"rev/m3", kRevolution, kRevolutionsPerVolume, "rad/m3"},
      {"N*m/rad", 1.0, kRotationalStiffness, "N*m/rad"},
      {"ft*lbf/rad", kFootPoundForce, kRotationalStiffness, "N*m/rad"},
      {"N*m/deg", 1.0 / kDegree, kRotationalStiffness, "N*m/rad"},
  };
  return conversions;
}

TEST(ParseUnit, EveryListedUnitHasItsExactFactorAndDimension) {
  for (const Conversion& conversion : AllConversions()) {
    SCOPED_TRACE(conversion.unit);
    const Unit unit = ParseUnit(conversion.unit);
    ExpectRelativelyNear(unit.to_si, conversion.to_si);
    EXPECT_EQ(unit.dimension, conversion.dimension);
  }
}

// The Energistics unit symbols WITSML's trajectory, tubular, wbGeometry and log objects write in `uom`
// (Energistics Unit of Measure Dictionary: dega, ftUS, lbm, the dot for a product), each with its
// exact factor: the US survey foot is 1200/3937 m, the degree of angle π/180 rad.
TEST(ParseUnit, EnergisticsSymbolsOfTheWitsmlObjects) {
  constexpr double kSurveyFoot = 1200.0 / 3937.0;
  const std::vector<Conversion> symbols = {
      {"m", 1.0, kLength, "m"}, {"ft", 0.3048, kLength, "m"}, {"ftUS", kSurveyFoot, kLength, "m"},
      {"in", 0.0254, kLength, "m"}, {"cm", 0.01, kLength, "m"}, {"mm", 1e-3, kLength, "m"},
      {"km", 1e3, kLength, "m"}, {"dega", kDegree, kAngle, "rad"}, {"rad", 1.0, kAngle, "rad"},
      {"lbm/ft", 0.45359237 / 0.3048, Dimension{-1, 1, 0, 0}, "kg/m"}, {"kg/m", 1.0, Dimension{-1, 1, 0, 0}, "kg/m"},
      {"dega/100ft", kDegree / 30.48, Dimension{-1, 0, 0, 1}, "rad/m"},
      {"dega/30m", kDegree / 30.0, Dimension{-1, 0, 0, 1}, "rad/m"},
      {"ft.lbf", 0.3048 * 4.4482216152605, Dimension{2, 1, -2, 0}, "N*m"},
      {"kN.m", 1e3, Dimension{2, 1, -2, 0}, "N*m"}, {"psi", 6894.757293168361, Dimension{-1, 1, -2, 0}, "Pa"},
      {"klbf", 4448.2216152605, kForce, "N"}, {"lbf/ft", 4.4482216152605 / 0.3048, Dimension{0, 1, -2, 0}, "N/m"},
      {"in2", 0.00064516, Dimension{2, 0, 0, 0}, "m2"},
      // A log's curves (rig readings): hook load and WOB in kgf and kkgf (1000 kgf, a tonne-force:
      // 1 kgf = 9.80665 N), torque in kN.m or kft.lbf, rotary speed in rpm.
      {"kgf", 9.80665, kForce, "N"}, {"kkgf", 9806.65, kForce, "N"},
      {"kft.lbf", 304.8 * 4.4482216152605, Dimension{2, 1, -2, 0}, "N*m"}, {"rpm", kRpm, kRotarySpeed, "rad/s"},
  };
  for (const Conversion& conversion : symbols) {
    SCOPED_TRACE(conversion.unit);
    const Unit unit = ParseUnit(conversion.unit);
    ExpectRelativelyNear(unit.to_si, conversion.to_si);
    EXPECT_EQ(unit.dimension, conversion.dimension);
  }
}

TEST(Convert, EveryListedUnitConvertsToSIAndBack) {
  for (const Conversion& conversion : AllConversions()) {
    SCOPED_TRACE(conversion.unit);
    ExpectRelativelyNear(Convert(2.5, conversion.unit, conversion.si_unit), 2.5 * conversion.to_si);
    ExpectRelativelyNear(Convert(2.5 * conversion.to_si, conversion.si_unit, conversion.unit), 2.5);
  }
}

TEST(Convert, BetweenTwoNonSIUnits) {
  ExpectRelativelyNear(Convert(1.0, "ft", "in"), 12.0);
  ExpectRelativelyNear(Convert(1.0, "ksi", "psi"), 1000.0);
  ExpectRelativelyNear(Convert(8.33, "ppg", "sg"), 8.33 * kPoundPerGallon / 1000.0);
  ExpectRelativelyNear(Convert(1.0, "deg/100ft", "deg/30m"), 30.0 / 30.48);
  ExpectRelativelyNear(Convert(1.0, "bbl/min", "gpm"), 42.0);
  ExpectRelativelyNear(Convert(1.0, "psi", "lbf/in2"), 1.0);
}

TEST(ParseUnit, AcceptsEveryWrittenForm) {
  struct Case {
    const char* expression;
    double to_si;
    Dimension dimension;
  };
  const std::vector<Case> cases{
      {"N\u00B7m", 1.0, kMoment},            // middle dot
      {"ft.lbf", kFootPoundForce, kMoment},  // dot between symbols
      {"ft lbf", kFootPoundForce, kMoment},  // space
      {"ft-lbf", kFootPoundForce, kMoment},  // hyphen between symbols
      {"N-m", 1.0, kMoment},
      {"s-1", 1.0, kFrequency},              // hyphen before a digit: an exponent
      {"kg\u00B7m\u00B2", 1.0, {2, 1, 0, 0}},
      {"m^-1", 1.0, {-1, 0, 0, 0}},
      {"m\u207B\u00B9", 1.0, {-1, 0, 0, 0}},  // m⁻¹
      {"s^-1", 1.0, kFrequency},
      {"1/s", 1.0, kFrequency},
      {"m/s^2", 1.0, kAcceleration},
      {"m/s\u00B2", 1.0, kAcceleration},
      {"deg/(100 ft)", kDegreePer100ft, kDogleg},
      {"deg/100 ft", kDegreePer100ft, kDogleg},
      {"\u00B0/100ft", kDegreePer100ft, kDogleg},
      {"100ft", 30.48, kLength},
      {"30.48cm", 0.3048, kLength},
      {"  psi  ", kPsi, kPressure},
      {"lbm/gal", kPoundPerGallon, kDensity},
      {"lb/ft^3", kPoundPerCubicFoot, kDensity},
      {"", 1.0, kDimensionless},
      {"%", 0.01, kDimensionless},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.expression);
    const Unit unit = ParseUnit(c.expression);
    ExpectRelativelyNear(unit.to_si, c.to_si);
    EXPECT_EQ(unit.dimension, c.dimension);
  }
}

TEST(ParseUnit, CaseIsFoldedOnlyWhereUnambiguous) {
  ExpectRelativelyNear(ParseUnit("cp").to_si, 1e-3);
  ExpectRelativelyNear(ParseUnit("CP").to_si, 1e-3);
  ExpectRelativelyNear(ParseUnit("pa").to_si, 1.0);
  ExpectRelativelyNear(ParseUnit("PSI").to_si, kPsi);
  ExpectRelativelyNear(ParseUnit("FT").to_si, 0.3048);
  ExpectRelativelyNear(ParseUnit("MPa").to_si, 1e6);
  ExpectRelativelyNear(ParseUnit("mPa").to_si, 1e-3);
  EXPECT_THROW(ParseUnit("mpa"), UnitError);  // milli or mega: refused, not guessed
  EXPECT_THROW(ParseUnit("n"), UnitError);    // N stays N
  EXPECT_THROW(ParseUnit("M"), UnitError);
}

TEST(UnitTable, SymbolsAreUniqueAndCaseFoldingIsUnambiguous) {
  const auto symbols = UnitSymbols();
  for (std::size_t i = 0; i < symbols.size(); ++i) {
    EXPECT_TRUE(std::isfinite(symbols[i].to_si) && symbols[i].to_si > 0.0) << symbols[i].symbol;
    for (std::size_t j = i + 1; j < symbols.size(); ++j) {
      EXPECT_NE(symbols[i].symbol, symbols[j].symbol);
      if (symbols[i].fold_case || symbols[j].fold_case) {
        EXPECT_NE(EditDistanceIgnoringCase(symbols[i].symbol, symbols[j].symbol), 0u)
            << symbols[i].symbol << " and " << symbols[j].symbol << " differ only by case";
      }
    }
  }
}

TEST(UnitTable, EditDistance) {
  EXPECT_EQ(EditDistanceIgnoringCase("kitten", "sitting"), 3u);
  EXPECT_EQ(EditDistanceIgnoringCase("pis", "psi"), 1u);  // one transposition
  EXPECT_EQ(EditDistanceIgnoringCase("", "abc"), 3u);
  EXPECT_EQ(EditDistanceIgnoringCase("PPG", "ppg"), 0u);
  EXPECT_EQ(EditDistanceIgnoringCase("ppgg", "ppg"), 1u);
}

// One of each default unit in SI, written out per quantity: {SI system, field system}.
struct DefaultFactor {
  Quantity quantity;
  double si_system;
  double field_system;
  const char* si_unit;
  const char* field_unit;
};

const std::vector<DefaultFactor>& AllDefaults() {
  static const std::vector<DefaultFactor> defaults{
      {Quantity::Dimensionless, 1.0, 1.0, "", ""},
      {Quantity::Length, 1.0, 0.3048, "m", "ft"},
      {Quantity::Diameter, 1.0, 0.0254, "m", "in"},
      {Quantity::Force, 1.0, 4.4482216152605, "N", "lbf"},
      {Quantity::WeightOnBit, 1.0, 4448.2216152605, "N", "klbf"},
      {Quantity::Moment, 1.0, kFootPoundForce, "N*m", "ft*lbf"},
      {Quantity::Density, 1.0, kPoundPerGallon, "kg/m3", "ppg"},
      {Quantity::Viscosity, 1.0, 1e-3, "Pa*s", "cP"},
      {Quantity::Stress, 1.0, kPsi, "Pa", "psi"},
      {Quantity::Angle, kDegree, kDegree, "deg", "deg"},
      {Quantity::RotarySpeed, kRpm, kRpm, "rpm", "rpm"},
      {Quantity::Time, 1.0, 1.0, "s", "s"},
      {Quantity::Mass, 1.0, 0.45359237, "kg", "lb"},
      {Quantity::MassPerLength, 1.0, kPoundPerFoot, "kg/m", "lb/ft"},
      {Quantity::ForcePerLength, 1.0, kPoundForcePerFoot, "N/m", "lbf/ft"},
      {Quantity::DoglegSeverity, kDegreePer30m, kDegreePer100ft, "deg/30m", "deg/100ft"},
      {Quantity::Imbalance, 1.0, kPoundInch, "kg*m", "lb*in"},
      {Quantity::Stiffness, 1.0, kPoundForcePerInch, "N/m", "lbf/in"},
      {Quantity::RotationalStiffness, 1.0, kFootPoundForce, "N*m/rad", "ft*lbf/rad"},
      {Quantity::Velocity, 1.0, 0.3048, "m/s", "ft/s"},
      {Quantity::Acceleration, 1.0, 1.0, "m/s2", "m/s2"},
      {Quantity::Frequency, 1.0, 1.0, "Hz", "Hz"},
      {Quantity::FlowRate, 1.0, kGallonPerMinute, "m3/s", "gpm"},
      {Quantity::RevolutionsPerVolume, kRevolution, kRevPerGallon, "rev/m3", "rev/gal"},
  };
  return defaults;
}

TEST(Quantities, EveryQuantityHasItsDefaultUnitsAndDimension) {
  ASSERT_EQ(AllDefaults().size(), static_cast<std::size_t>(Quantity::RevolutionsPerVolume) + 1);
  for (const DefaultFactor& d : AllDefaults()) {
    SCOPED_TRACE(QuantityName(d.quantity));
    EXPECT_EQ(DefaultUnit(d.quantity, System::SI), d.si_unit);
    EXPECT_EQ(DefaultUnit(d.quantity, System::Field), d.field_unit);
    EXPECT_EQ(ParseUnit(DefaultUnit(d.quantity, System::SI)).dimension, DimensionOf(d.quantity));
    EXPECT_EQ(ParseUnit(DefaultUnit(d.quantity, System::Field)).dimension, DimensionOf(d.quantity));
  }
  EXPECT_EQ(DimensionOf(Quantity::Diameter), kLength);
  EXPECT_EQ(DimensionOf(Quantity::WeightOnBit), kForce);
  EXPECT_EQ(DimensionOf(Quantity::Stiffness), kForcePerLength);
  EXPECT_EQ(DimensionOf(Quantity::DoglegSeverity), kDogleg);
}

TEST(Quantities, ToSIUsesTheDefaultUnitAndFromSIInvertsIt) {
  for (const DefaultFactor& d : AllDefaults()) {
    SCOPED_TRACE(QuantityName(d.quantity));
    for (double value : {1.0, -3.75, 12345.678, 1e-7}) {
      ExpectRelativelyNear(ToSI(value, d.quantity, System::SI), value * d.si_system);
      ExpectRelativelyNear(ToSI(value, d.quantity, System::Field), value * d.field_system);
      for (System system : {System::SI, System::Field}) {
        ExpectRelativelyNear(FromSI(ToSI(value, d.quantity, system), d.quantity, system), value,
                             1e-14);
        ExpectRelativelyNear(ToSI(FromSI(value, d.quantity, system), d.quantity, system), value,
                             1e-14);
      }
    }
  }
}

TEST(ParseQuantity, ValuesWithTheirOwnUnitIgnoreTheSystem) {
  for (System system : {System::SI, System::Field}) {
    ExpectRelativelyNear(ParseQuantity("8.5 in", Quantity::Diameter, system), 0.2159);
    ExpectRelativelyNear(ParseQuantity("30 ft", Quantity::Length, system), 9.144);
    ExpectRelativelyNear(ParseQuantity("12.5 ppg", Quantity::Density, system), 12.5 * kPoundPerGallon);
    ExpectRelativelyNear(ParseQuantity("25 klbf", Quantity::WeightOnBit, system), 111205.5403815125);
    ExpectRelativelyNear(ParseQuantity("15000 ft*lbf", Quantity::Moment, system),
                         15000.0 * kFootPoundForce);
    ExpectRelativelyNear(ParseQuantity("2.1e11 Pa", Quantity::Stress, system), 2.1e11);
    ExpectRelativelyNear(ParseQuantity("30e6 psi", Quantity::Stress, system), 30e6 * kPsi);
    ExpectRelativelyNear(ParseQuantity("120 rpm", Quantity::RotarySpeed, system), 2.0 * kRevolution);
    ExpectRelativelyNear(ParseQuantity("3 deg/100ft", Quantity::DoglegSeverity, system),
                         3.0 * kDegreePer100ft);
    ExpectRelativelyNear(ParseQuantity("8.5in", Quantity::Diameter, system), 0.2159);
    ExpectRelativelyNear(ParseQuantity("  -5 m \t", Quantity::Length, system), -5.0);
    ExpectRelativelyNear(ParseQuantity("+5 m", Quantity::Length, system), 5.0);
    ExpectRelativelyNear(ParseQuantity("30 1/s", Quantity::Frequency, system), 30.0);
    ExpectRelativelyNear(ParseQuantity("50 %", Quantity::Dimensionless, system), 0.5);
    ExpectRelativelyNear(ParseQuantity("400 gpm", Quantity::FlowRate, system),
                         400.0 * kGallonPerMinute);
  }
}

TEST(ParseQuantity, BareNumbersTakeTheSystemsDefaultUnit) {
  ExpectRelativelyNear(ParseQuantity("8.5", Quantity::Diameter, System::Field), 0.2159);
  ExpectRelativelyNear(ParseQuantity("0.2159", Quantity::Diameter, System::SI), 0.2159);
  ExpectRelativelyNear(ParseQuantity("6000", Quantity::Length, System::Field), 1828.8);
  ExpectRelativelyNear(ParseQuantity("10.5", Quantity::Density, System::Field),
                       10.5 * kPoundPerGallon);
  ExpectRelativelyNear(ParseQuantity("1250", Quantity::Density, System::SI), 1250.0);
  ExpectRelativelyNear(ParseQuantity("20", Quantity::Viscosity, System::Field), 0.02);
  ExpectRelativelyNear(ParseQuantity("25", Quantity::WeightOnBit, System::Field), 111205.5403815125);
  ExpectRelativelyNear(ParseQuantity("30", Quantity::Angle, System::SI), 30.0 * kDegree);
  ExpectRelativelyNear(ParseQuantity("3", Quantity::DoglegSeverity, System::SI), 3.0 * kDegreePer30m);
  ExpectRelativelyNear(ParseQuantity("9.81", Quantity::Acceleration, System::Field), 9.81);
  ExpectRelativelyNear(ParseQuantity("1e-3", Quantity::Time, System::SI), 1e-3);
}

TEST(ParseQuantity, MixedFractions) {
  ExpectRelativelyNear(ParseQuantity("8-1/2 in", Quantity::Diameter, System::SI), 0.2159);
  ExpectRelativelyNear(ParseQuantity("8 1/2 in", Quantity::Diameter, System::SI), 0.2159);
  ExpectRelativelyNear(ParseQuantity("8-1/2in", Quantity::Diameter, System::SI), 0.2159);
  ExpectRelativelyNear(ParseQuantity("9 5/8 in", Quantity::Diameter, System::SI), 0.244475);
  ExpectRelativelyNear(ParseQuantity("1/2 in", Quantity::Diameter, System::SI), 0.0127);
  ExpectRelativelyNear(ParseQuantity("12-1/4", Quantity::Diameter, System::Field), 0.31115);
  ExpectRelativelyNear(ParseQuantity("3/4", Quantity::Diameter, System::Field), 0.01905);
  ExpectRelativelyNear(ParseQuantity("-8-1/2 in", Quantity::Diameter, System::SI), -0.2159);
  ExpectRelativelyNear(ParseQuantity("-1/2 in", Quantity::Diameter, System::SI), -0.0127);
}

TEST(ParseQuantity, WrongDimensionNamesBothKinds) {
  const auto message = [](const char* text, Quantity quantity) -> std::string {
    try {
      ParseQuantity(text, quantity, System::Field);
    } catch (const UnitError& error) {
      return error.what();
    }
    ADD_FAILURE() << text << " was accepted";
    return {};
  };
  EXPECT_THAT(message("12.5 ppg", Quantity::Diameter),
              HasSubstr("\"12.5 ppg\" is a density, but a diameter (length) is expected"));
  EXPECT_THAT(message("12.5 ppg", Quantity::Diameter), HasSubstr("field unit: in"));
  EXPECT_THAT(message("30 ft", Quantity::Density), HasSubstr("is a length, but a density is expected"));
  EXPECT_THAT(message("100 rpm", Quantity::Frequency),
              HasSubstr("is a rotary speed, but a frequency is expected"));
  EXPECT_THAT(message("3 1/m", Quantity::DoglegSeverity),
              HasSubstr("is a quantity in m^-1, but a dogleg severity (angle per length) is expected"));
  EXPECT_THAT(message("3 m2/s", Quantity::Length), HasSubstr("is a quantity in m^2 s^-1"));
  EXPECT_THAT(message("5 klbf", Quantity::Moment),
              HasSubstr("is a force, but a moment or torque (force x length) is expected"));
  EXPECT_THAT(message("5 psi", Quantity::Dimensionless), HasSubstr("(a bare number)"));
}

std::string ErrorOf(const std::function<void()>& action) {
  try {
    action();
  } catch (const UnitError& error) {
    return error.what();
  }
  ADD_FAILURE() << "no UnitError";
  return {};
}

TEST(ParseQuantity, UnknownUnitNamesItAndSuggestsCloseOnes) {
  const std::string typo = ErrorOf([] { ParseQuantity("12.5 ppgg", Quantity::Density, System::SI); });
  EXPECT_THAT(typo, HasSubstr("\"12.5 ppgg\": unknown unit \"ppgg\""));
  EXPECT_THAT(typo, HasSubstr("did you mean \"ppg\""));
  const std::string transposed = ErrorOf([] { ParseQuantity("30 pis", Quantity::Stress, System::SI); });
  EXPECT_THAT(transposed, HasSubstr("did you mean \"psi\""));
  const std::string ambiguous = ErrorOf([] { ParseUnit("mpa"); });
  EXPECT_THAT(ambiguous, HasSubstr("\"mPa\""));
  EXPECT_THAT(ambiguous, HasSubstr("\"MPa\""));
  const std::string inside = ErrorOf([] { ParseUnit("ft*lbz"); });
  EXPECT_THAT(inside, HasSubstr("unknown unit \"lbz\" in \"ft*lbz\""));
  EXPECT_THAT(inside, HasSubstr("\"lb\""));
  const std::string far = ErrorOf([] { ParseQuantity("5 xyzzy", Quantity::Length, System::SI); });
  EXPECT_THAT(far, HasSubstr("unknown unit \"xyzzy\""));
  EXPECT_THAT(far, HasSubstr("known units include m, mm, in, ft"));
}

TEST(ParseQuantity, TextThatIsNotANumberIsRefused) {
  const auto error = [](const char* text) {
    return ErrorOf([text] { ParseQuantity(text, Quantity::Diameter, System::Field); });
  };
  EXPECT_THAT(error("abc in"), HasSubstr("expected a number with an optional unit"));
  EXPECT_THAT(error("abc in"), HasSubstr("but got \"abc in\""));
  EXPECT_THAT(error(""), HasSubstr("expected a number with an optional unit"));
  EXPECT_THAT(error(""), HasSubstr("the value is empty"));
  EXPECT_THAT(error("   "), HasSubstr("the value is empty"));
  EXPECT_THAT(error("in"), HasSubstr("expected a number"));
  EXPECT_THAT(error("+-5"), HasSubstr("expected a number"));
  EXPECT_THAT(error("nan"), HasSubstr("\"nan\" is not a finite number"));
  EXPECT_THAT(error("inf in"), HasSubstr("is not a finite number"));
  EXPECT_THAT(error("-infinity"), HasSubstr("is not a finite number"));
  EXPECT_THAT(error("1e400 in"), HasSubstr("out of range"));
  EXPECT_THAT(ErrorOf([] { ParseQuantity("1e306 klbf*km", Quantity::Moment, System::SI); }),
              HasSubstr("\"1e306 klbf*km\" is out of range"));
  EXPECT_THAT(ErrorOf([] { ParseQuantity("1e308", Quantity::WeightOnBit, System::Field); }),
              HasSubstr("\"1e308\" is out of range"));
}

TEST(ParseUnit, MalformedExpressionsAreRefused) {
  EXPECT_THAT(ErrorOf([] { ParseUnit("m/s/s"); }), HasSubstr("only one '/' is allowed"));
  EXPECT_THAT(ErrorOf([] { ParseUnit("m/"); }), HasSubstr("nothing after '/'"));
  EXPECT_THAT(ErrorOf([] { ParseUnit("/s"); }), HasSubstr("nothing before '/'"));
  EXPECT_THAT(ErrorOf([] { ParseUnit("m^"); }), HasSubstr("'^' must be followed by an integer"));
  EXPECT_THAT(ErrorOf([] { ParseUnit("m^0"); }), HasSubstr("an exponent of 0 is not allowed"));
  EXPECT_THAT(ErrorOf([] { ParseUnit("^2"); }), HasSubstr("needs a unit symbol before it"));
  EXPECT_THAT(ErrorOf([] { ParseUnit("deg/0ft"); }), HasSubstr("must be positive and finite"));
}

// Found by fuzz/unit_expression (fuzz/README.md): each was read as a unit of infinite (or zero)
// factor, or overflowed an int exponent, instead of a UnitError.
TEST(ParseUnit, FuzzFindingsAreRefused) {
  EXPECT_THAT(ErrorOf([] { ParseUnit("ft250"); }), HasSubstr("an exponent must lie between -9 and 9"));
  EXPECT_THAT(ErrorOf([] { ParseUnit("t250"); }), HasSubstr("an exponent must lie between -9 and 9"));
  EXPECT_THAT(ErrorOf([] { Convert(1.0, "t250", "t250"); }), HasSubstr("exponent"));
  EXPECT_THAT(ErrorOf([] { ParseUnit("m^99999999999"); }), HasSubstr("an exponent must lie between"));
  EXPECT_THAT(ErrorOf([] { ParseUnit("m\u00B2\u00B2"); }), HasSubstr("an exponent must lie between"));
  // Products within the powers' bound whose factor no double holds: 1e594 and 1e-594.
  const auto repeated = [](const std::string& factor, int count) {
    std::string text;
    for (int i = 0; i < count; ++i) text += factor + " ";
    return text;
  };
  EXPECT_THAT(ErrorOf([&] { ParseUnit(repeated("km9", 11) + repeated("t9", 11)); }),
              HasSubstr("its size in SI units is out of range"));
  EXPECT_THAT(ErrorOf([&] { ParseUnit(repeated("mm9", 11) + repeated("g9", 11)); }),
              HasSubstr("its size in SI units is out of range"));
  EXPECT_THAT(ErrorOf([&] { ParseUnit(repeated("m9", 12)); }), HasSubstr("power goes past 99"));
  EXPECT_EQ(ParseUnit("m9").dimension.length, 9);
  EXPECT_EQ(ParseUnit("m^-9").dimension.length, -9);
}

TEST(Convert, WrongDimensionNamesBothKinds) {
  const std::string message = ErrorOf([] { Convert(1.0, "ppg", "in"); });
  EXPECT_THAT(message, HasSubstr("cannot convert from \"ppg\" (a density) to \"in\" (a length)"));
  EXPECT_THROW(Convert(1.0, "rpm", "Hz"), UnitError);  // angle is its own dimension
  EXPECT_THROW(Convert(1.0, "deg/100ft", "1/m"), UnitError);
}

TEST(Names, DimensionNamesAreFriendly) {
  EXPECT_EQ(DimensionName(kLength), "a length");
  EXPECT_EQ(DimensionName(kForce), "a force");
  EXPECT_EQ(DimensionName(kMoment), "a moment (force x length)");
  EXPECT_EQ(DimensionName(kDensity), "a density");
  EXPECT_EQ(DimensionName(kPressure), "a pressure or stress");
  EXPECT_EQ(DimensionName(kViscosity), "a dynamic viscosity");
  EXPECT_EQ(DimensionName(kAngle), "an angle");
  EXPECT_EQ(DimensionName(kRotarySpeed), "a rotary speed");
  EXPECT_EQ(DimensionName(kTime), "a time");
  EXPECT_EQ(DimensionName(kMass), "a mass");
  EXPECT_EQ(DimensionName(kMassPerLength), "a mass per length");
  EXPECT_EQ(DimensionName(kForcePerLength), "a force per length");
  EXPECT_EQ(DimensionName(kDogleg), "an angle per length (dogleg severity)");
  EXPECT_EQ(DimensionName(kImbalance), "a mass x length (imbalance)");
  EXPECT_EQ(DimensionName(kVelocity), "a velocity");
  EXPECT_EQ(DimensionName(kAcceleration), "an acceleration");
  EXPECT_EQ(DimensionName(kFrequency), "a frequency");
  EXPECT_EQ(DimensionName(kFlowRate), "a flow rate");
  EXPECT_EQ(DimensionName(kDimensionless), "a dimensionless number");
  EXPECT_EQ(DimensionName(Dimension{2, 0, -1, 0}), "a quantity in m^2 s^-1");
  EXPECT_EQ(DimensionName(Dimension{1, -1, 3, 2}), "a quantity in m kg^-1 s^3 rad^2");
  EXPECT_EQ(QuantityName(Quantity::Diameter), "a diameter (length)");
  EXPECT_EQ(QuantityName(Quantity::Density), "a density");
}

TEST(Systems, ParseAndName) {
  for (const char* text : {"SI", "si", " Si "}) EXPECT_EQ(ParseSystem(text), System::SI) << text;
  for (const char* text : {"field", "Field", "FIELD"}) {
    EXPECT_EQ(ParseSystem(text), System::Field) << text;
  }
  EXPECT_EQ(SystemName(System::SI), "SI");
  EXPECT_EQ(SystemName(System::Field), "field");
  EXPECT_EQ(ParseSystem(SystemName(System::Field)), System::Field);
  EXPECT_THAT(ErrorOf([] { ParseSystem("metric"); }),
              HasSubstr("unknown unit system \"metric\": expected \"SI\" or \"field\""));
  EXPECT_THROW(ParseSystem(""), UnitError);
}

}  // namespace units_test
}  // namespace drillflex::units
