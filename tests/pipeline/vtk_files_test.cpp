// The VTK XML files of a static result (io/vtk_files.hpp), read back as text: the bundled example
// solved in its well (string.vtp: one point per station in order on one polyline, the values and
// the places in SI to 1e-9; well.vtp over the string's MD range; contacts.vtp one vertex per
// contact, its normal toward the hole axis), and a constructed result without a well or contacts
// (no well.vtp, no contacts.vtp; a NaN, an infinity and a −0 written as 0). A transient's frames
// (the V8 cantilever released for 40 ms, 5 frames): transient.pvd lists string_0000.vtp to
// string_0004.vtp at increasing times, each a string.vtp of the stations at that time.
#include "io/vtk_files.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "pipeline/case_run.hpp"
#include "model/builder.hpp"

namespace drillflex::io {
namespace vtk_files_test {

namespace fs = std::filesystem;

constexpr double kIn = 0.0254;

// ---- A minimal reading of the XML: tags found by text ----

std::string ReadFile(const fs::path& path) {
  std::ifstream file(path);
  std::stringstream text;
  text << file.rdbuf();
  return text.str();
}

// The start tag "<tag ...>" of the first element `tag` at or after `from` ("" when none).
std::string StartTag(const std::string& text, const std::string& tag, std::size_t from = 0) {
  const std::size_t start = text.find("<" + tag + " ", from);
  if (start == std::string::npos) return "";
  return text.substr(start, text.find('>', start) - start + 1);
}

std::string Attribute(const std::string& start_tag, const std::string& name) {
  const std::string key = " " + name + "=\"";
  const std::size_t start = start_tag.find(key);
  if (start == std::string::npos) return "";
  const std::size_t value = start + key.size();
  return start_tag.substr(value, start_tag.find('"', value) - value);
}

// The text from <tag> (or <tag attributes...>) to </tag> (the first such element).
std::string Element(const std::string& text, const std::string& tag) {
  std::size_t open = text.find("<" + tag + ">");
  if (open == std::string::npos) open = text.find("<" + tag + " ");
  const std::size_t close = text.find("</" + tag + ">");
  if (open == std::string::npos || close == std::string::npos) return "";
  return text.substr(open, close - open);
}

std::vector<double> ParseNumbers(const std::string& text) {
  std::istringstream stream(text);
  std::vector<double> values;
  for (double value; stream >> value;) values.push_back(value);
  EXPECT_TRUE(stream.eof()) << "not a number in: " << text.substr(0, 200);
  return values;
}

// The values of the DataArray whose start tag holds `attribute` (e.g. Name="axial_force"), or of the
// first DataArray when `attribute` is ""; with its NumberOfComponents (1 when absent).
struct ArrayData {
  int components = 0;  // 0: no such array
  std::vector<double> values;
};
ArrayData FindArray(const std::string& text, const std::string& attribute = "") {
  std::size_t from = 0;
  for (std::string tag; !(tag = StartTag(text, "DataArray", from)).empty();) {
    const std::size_t start = text.find(tag, from);
    from = start + tag.size();
    if (!attribute.empty() && tag.find(" " + attribute) == std::string::npos) continue;
    EXPECT_EQ(Attribute(tag, "format"), "ascii");
    const std::string components = Attribute(tag, "NumberOfComponents");
    return {components.empty() ? 1 : std::stoi(components),
            ParseNumbers(text.substr(from, text.find("</DataArray>", from) - from))};
  }
  return {};
}

std::vector<double> PointValues(const std::string& text, const std::string& name, int components = 1) {
  const ArrayData array = FindArray(Element(text, "PointData"), "Name=\"" + name + "\"");
  EXPECT_EQ(array.components, components) << name;
  return array.values;
}

// Relative to the expected value (an exact 0 must read back as 0).
void ExpectRelativelyNear(double actual, double expected, const std::string& what) {
  EXPECT_LE(std::abs(actual - expected), 1e-9 * std::abs(expected)) << what << ": " << actual << " vs " << expected;
}

void ExpectRoot(const std::string& text) {
  EXPECT_NE(text.find("<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\">"), std::string::npos);
  EXPECT_NE(text.find("</VTKFile>"), std::string::npos);
  EXPECT_EQ(text.find("nan"), std::string::npos);
  EXPECT_EQ(text.find("inf"), std::string::npos);
}

std::size_t PieceCount(const std::string& text, const std::string& attribute) {
  return std::stoul(Attribute(StartTag(text, "Piece"), attribute));
}

// connectivity and offsets of the <Lines> or <Verts>.
struct CellArrays {
  std::vector<double> connectivity, offsets;
};
CellArrays Cells(const std::string& text, const std::string& tag) {
  const std::string cells = Element(text, tag);
  return {FindArray(cells, "Name=\"connectivity\"").values, FindArray(cells, "Name=\"offsets\"").values};
}

fs::path Commit(ResultFiles& files) {
  files.Commit();
  return files.directory();
}

ResultFiles FilesIn(const std::string& name) {
  const fs::path directory = fs::path(DRILLFLEX_BINARY_DIR) / "vtk-files-test" / name;
  fs::remove_all(directory);
  return ResultFiles(directory.string());
}

// ---- The bundled example in its well ----

TEST(VtkFiles, BundledExampleStringWellAndContactsReadBackInSi) {
  const Case c = ReadCase((fs::path(DRILLFLEX_SOURCE_DIR) / "examples/rotary-bha-build/case.yaml").string());
  const pipeline::CaseResults run = pipeline::RunCase(c, pipeline::AnalysisRequest::Only(pipeline::Analysis::Static));
  const model::BuiltModel& built = run.model.built;
  const analyses::StaticResult& result = *run.static_result;
  ResultFiles files = FilesIn("bundled");
  AddStaticVtk(c, built, result, files);
  const fs::path directory = Commit(files);

  // string.vtp: one point per station, in order, on one polyline.
  const std::string string_vtp = ReadFile(directory / "string.vtp");
  ExpectRoot(string_vtp);
  const std::size_t n = result.nodes.size();
  ASSERT_GT(n, 100u);
  EXPECT_EQ(PieceCount(string_vtp, "NumberOfPoints"), n);
  EXPECT_EQ(PieceCount(string_vtp, "NumberOfLines"), 1u);
  EXPECT_EQ(PieceCount(string_vtp, "NumberOfVerts"), 0u);
  const CellArrays line = Cells(string_vtp, "Lines");
  ASSERT_EQ(line.connectivity.size(), n);
  for (std::size_t i = 0; i < n; ++i) EXPECT_EQ(line.connectivity[i], static_cast<double>(i));
  EXPECT_EQ(line.offsets, std::vector<double>{static_cast<double>(n)});
  const ArrayData points = FindArray(Element(string_vtp, "Points"));
  ASSERT_EQ(points.components, 3);
  ASSERT_EQ(points.values.size(), 3 * n);
  const std::vector<double> s = PointValues(string_vtp, "s");
  const std::vector<double> axial_force = PointValues(string_vtp, "axial_force");
  const std::vector<double> von_mises = PointValues(string_vtp, "von_mises_stress");
  const std::vector<double> displacement = PointValues(string_vtp, "displacement", 3);
  const std::vector<double> rotation = PointValues(string_vtp, "rotation", 3);
  const std::vector<double> clearance = PointValues(string_vtp, "clearance");
  const std::vector<double> outer_radius = PointValues(string_vtp, "outer_radius");
  ASSERT_EQ(s.size(), n);
  ASSERT_EQ(axial_force.size(), n);
  ASSERT_EQ(von_mises.size(), n);
  ASSERT_EQ(displacement.size(), 3 * n);
  ASSERT_EQ(rotation.size(), 3 * n);
  ASSERT_EQ(clearance.size(), n);
  ASSERT_EQ(outer_radius.size(), n);
  for (std::size_t i = 0; i < n; ++i) {
    const analyses::StaticNodeResult& node = result.nodes[i];
    const std::string at = "station " + std::to_string(i);
    ExpectRelativelyNear(s[i], node.s, at + " s");
    ExpectRelativelyNear(axial_force[i], node.axial_force, at + " axial_force");
    ExpectRelativelyNear(von_mises[i], node.von_mises_stress, at + " von_mises_stress");
    ExpectRelativelyNear(clearance[i], node.clearance, at + " clearance");
    for (int k = 0; k < 3; ++k) {
      ExpectRelativelyNear(points.values[3 * i + k], node.position[k], at + " position");
      ExpectRelativelyNear(displacement[3 * i + k], node.displacement[k], at + " displacement");
      ExpectRelativelyNear(rotation[3 * i + k], node.rotation[k], at + " rotation (rad)");
    }
  }
  EXPECT_NEAR(outer_radius.front(), 0.5 * 8.5 * kIn, 1e-12);  // the bit
  EXPECT_NEAR(outer_radius.back(), 0.5 * 5.0 * kIn, 1e-12);   // the drill pipe at the top
  // The string's nodes are tens of metres deep in the well (global z down, TVD), the top shallower.
  EXPECT_GT(points.values[2], points.values[3 * n - 1]);

  // well.vtp: the hole's axis over the string's MD range, the open hole's diameter.
  const std::string well_vtp = ReadFile(directory / "well.vtp");
  ExpectRoot(well_vtp);
  const std::size_t well_points = PieceCount(well_vtp, "NumberOfPoints");
  EXPECT_EQ(PieceCount(well_vtp, "NumberOfLines"), 1u);
  const std::vector<double> md = PointValues(well_vtp, "md");
  const std::vector<double> hole_diameter = PointValues(well_vtp, "hole_diameter");
  ASSERT_EQ(md.size(), well_points);
  ASSERT_EQ(hole_diameter.size(), well_points);
  EXPECT_EQ(PointValues(well_vtp, "inclination").size(), well_points);
  EXPECT_EQ(PointValues(well_vtp, "azimuth").size(), well_points);
  EXPECT_EQ(FindArray(Element(well_vtp, "Points")).values.size(), 3 * well_points);
  EXPECT_EQ(Cells(well_vtp, "Lines").connectivity.size(), well_points);
  ASSERT_GE(well_points, n);  // at least every station's MD
  EXPECT_TRUE(std::is_sorted(md.begin(), md.end()));
  // From the shallowest station's MD (in the hole's cross-section through it) to the deepest's.
  const auto [shallowest, deepest] = std::minmax_element(
      result.nodes.begin(), result.nodes.end(), [](const auto& a, const auto& b) { return a.md < b.md; });
  ExpectRelativelyNear(md.front(), shallowest->md, "the well's top MD");
  ExpectRelativelyNear(md.back(), deepest->md, "the well's bottom MD");
  EXPECT_NEAR(md.back(), c.well->bit_md, 0.5);
  EXPECT_NEAR(md.front(), c.well->bit_md - result.nodes.back().s, 0.5);
  for (const double d : hole_diameter) EXPECT_NEAR(d, 8.5 * kIn, 1e-12);  // all below the casing at 4500 ft

  // contacts.vtp: one vertex per wall contact carrying force; the normal points from the wall toward
  // the hole's axis.
  ASSERT_FALSE(result.contacts.empty());
  const std::string contacts_vtp = ReadFile(directory / "contacts.vtp");
  ExpectRoot(contacts_vtp);
  const std::size_t m = result.contacts.size();
  EXPECT_EQ(PieceCount(contacts_vtp, "NumberOfPoints"), m);
  EXPECT_EQ(PieceCount(contacts_vtp, "NumberOfVerts"), m);
  EXPECT_EQ(PieceCount(contacts_vtp, "NumberOfLines"), 0u);
  EXPECT_EQ(Cells(contacts_vtp, "Verts").offsets.size(), m);
  const std::vector<double> contact_points = FindArray(Element(contacts_vtp, "Points")).values;
  const std::vector<double> normal_force = PointValues(contacts_vtp, "normal_force");
  const std::vector<double> normal = PointValues(contacts_vtp, "normal", 3);
  const std::vector<double> force = PointValues(contacts_vtp, "normal_force_vector", 3);
  ASSERT_EQ(contact_points.size(), 3 * m);
  ASSERT_EQ(normal_force.size(), m);
  ASSERT_EQ(normal.size(), 3 * m);
  ASSERT_EQ(force.size(), 3 * m);
  EXPECT_EQ(PointValues(contacts_vtp, "component").size(), m);
  const well::Trajectory trajectory(c.well->survey);
  for (std::size_t j = 0; j < m; ++j) {
    const analyses::ContactReport& contact = result.contacts[j];
    ExpectRelativelyNear(normal_force[j], contact.normal_force, "normal_force");
    const Vec3 point(contact_points[3 * j], contact_points[3 * j + 1], contact_points[3 * j + 2]);
    const Vec3 direction(normal[3 * j], normal[3 * j + 1], normal[3 * j + 2]);
    const Vec3 on_string(force[3 * j], force[3 * j + 1], force[3 * j + 2]);
    EXPECT_NEAR(direction.norm(), 1.0, 1e-12);
    EXPECT_NEAR((on_string - contact.normal_force * direction).norm(), 0.0, 1e-9 * contact.normal_force);
    // The contact point lies about a hole radius off the axis, the normal pointing back at it.
    const Vec3 off_axis = point - trajectory.Position(contact.md);
    EXPECT_NEAR(off_axis.norm(), 0.5 * 8.5 * kIn, 0.001) << "contact " << j;
    EXPECT_LT(direction.dot(off_axis.normalized()), -0.999) << "contact " << j;
  }
}

// ---- No well, no contacts; numbers VTK would not read ----

TEST(VtkFiles, ContactFreeCaseWithoutAWellWritesOnlyTheStringAndNoNonFiniteNumbers) {
  Case c;
  c.name = "no well";
  model::Component collar;
  collar.name = "collar";
  collar.outer_diameter = 6.75 * kIn;
  collar.length = 10.0;
  c.input.string.components = {collar};
  const model::BuiltModel built{.system = model::SystemModel({}, {}, 10.0)};
  analyses::StaticResult result;
  for (int i = 0; i <= 4; ++i) {
    analyses::StaticNodeResult node;
    node.s = node.position.x() = 2.5 * i;
    node.axial_force = -1000.0 * i;
    result.nodes.push_back(node);
  }
  result.nodes[1].torque = -0.0;
  result.nodes[2].von_mises_stress = std::numeric_limits<double>::quiet_NaN();
  result.nodes[3].bending_moment = -std::numeric_limits<double>::infinity();
  ResultFiles files = FilesIn("no-well");
  AddStaticVtk(c, built, result, files);
  const fs::path directory = Commit(files);

  EXPECT_TRUE(fs::exists(directory / "string.vtp"));
  EXPECT_FALSE(fs::exists(directory / "well.vtp"));
  EXPECT_FALSE(fs::exists(directory / "contacts.vtp"));
  const std::string string_vtp = ReadFile(directory / "string.vtp");
  ExpectRoot(string_vtp);
  EXPECT_EQ(string_vtp.find("-0 "), std::string::npos);
  EXPECT_EQ(string_vtp.find("-0\n"), std::string::npos);
  EXPECT_NE(string_vtp.find("<!-- 2 values that were not finite written as 0 -->"), std::string::npos);
  EXPECT_EQ(PieceCount(string_vtp, "NumberOfPoints"), 5u);
  EXPECT_EQ(PointValues(string_vtp, "torque")[1], 0.0);
  EXPECT_FALSE(std::signbit(PointValues(string_vtp, "torque")[1]));
  EXPECT_EQ(PointValues(string_vtp, "von_mises_stress")[2], 0.0);
  EXPECT_EQ(PointValues(string_vtp, "bending_moment")[3], 0.0);
  EXPECT_EQ(PointValues(string_vtp, "axial_force")[4], -4000.0);
  EXPECT_EQ(PointValues(string_vtp, "md")[4], 10.0);  // s without a well
  EXPECT_EQ(FindArray(Element(string_vtp, "PointData"), "Name=\"clearance\"").components, 0);  // no place in a hole
  EXPECT_NEAR(PointValues(string_vtp, "outer_radius")[0], 0.5 * 6.75 * kIn, 1e-15);
}

// ---- A transient's frames: transient.pvd and string_NNNN.vtp ----

// The V8 cantilever (validation/v8-transient/free-vibration.yaml: 200 in rod, 4 bodies of 10
// elements) released from its deflection under 100 N at the tip, for 40 ms.
constexpr const char* kReleasedCantilever = R"(name: released-cantilever
units: SI
materials:
  rod: {E: 2.1e11 Pa, nu: 0.3, density: 7800 kg/m3}
string:
  - {type: collar, name: rod, od: 3 in, id: 0, length: 200 in, material: rod}
model: {body_length: 50 in, elements_per_body: 10, modes_per_body: 6, rotary_inertia: false,
        structural_damping: 0}
supports:
  - {at: 0, fix: all}
analyses:
  transient:
    initial_loads:
      - {at: 200 in, force: [0, 0, 100 N]}
    duration: 40 ms
    output_interval: 2 ms
    time_step: 0.5 ms
    rho_infinity: 1
    tolerance: 1e-8
    vtk_frames: 5
)";

TEST(VtkFiles, TransientFramesAreACollectionOfStringFilesAtTheirTimes) {
  const Case c = ParseCase(kReleasedCantilever, "released-cantilever.yaml");
  ASSERT_EQ(c.analyses.transient->vtk_frames, 5);
  // As the command line runs it with VTK output: the frames kept.
  pipeline::RunOptions options;
  options.keep_transient_shapes = true;
  const pipeline::CaseResults run =
      pipeline::RunCase(c, pipeline::AnalysisRequest::Only(pipeline::Analysis::Transient), options);
  const model::BuiltModel& moving = run.transient_setup->moving;
  const analyses::TransientResult& result = *run.transient;
  // 21 samples: every 5th (⌈20 / 4⌉) is a frame, t = 0 and the end among them.
  ASSERT_EQ(result.frame_q.size(), 5u);
  EXPECT_EQ(result.frame_times.front(), 0.0);
  EXPECT_EQ(result.frame_times.back(), 0.04);
  EXPECT_EQ(result.frame_q.back(), result.final_q);

  ResultFiles files = FilesIn("transient");
  AddTransientVtk(c, moving, result, files);
  const fs::path directory = Commit(files);

  // transient.pvd: one data set per frame, at increasing times.
  const std::string pvd = ReadFile(directory / "transient.pvd");
  EXPECT_NE(pvd.find("<VTKFile type=\"Collection\" version=\"1.0\""), std::string::npos);
  EXPECT_NE(pvd.find("</Collection>\n</VTKFile>"), std::string::npos);
  std::vector<std::string> frame_files;
  std::vector<double> times;
  for (std::size_t from = 0; !StartTag(pvd, "DataSet", from).empty();) {
    const std::string tag = StartTag(pvd, "DataSet", from);
    from = pvd.find(tag, from) + tag.size();
    EXPECT_EQ(Attribute(tag, "part"), "0");
    times.push_back(std::stod(Attribute(tag, "timestep")));
    frame_files.push_back(Attribute(tag, "file"));
  }
  ASSERT_EQ(frame_files.size(), 5u);
  EXPECT_EQ(frame_files.front(), "string_0000.vtp");
  EXPECT_EQ(frame_files.back(), "string_0004.vtp");
  EXPECT_EQ(times, result.frame_times);
  EXPECT_TRUE(std::is_sorted(times.begin(), times.end()) &&
              std::adjacent_find(times.begin(), times.end()) == times.end());

  // Each frame: the string.vtp form, one point per station on one polyline.
  const std::vector<analyses::StaticNodeResult> at_end = analyses::StaticNodeResults(moving, result.final_q);
  const std::size_t n = at_end.size();
  ASSERT_GT(n, 40u);
  std::vector<std::string> frames;
  for (const std::string& name : frame_files) {
    frames.push_back(ReadFile(directory / name));
    const std::string& vtp = frames.back();
    ExpectRoot(vtp);
    EXPECT_EQ(PieceCount(vtp, "NumberOfPoints"), n) << name;
    EXPECT_EQ(PieceCount(vtp, "NumberOfLines"), 1u) << name;
    EXPECT_EQ(FindArray(Element(vtp, "Points")).values.size(), 3 * n) << name;
    EXPECT_EQ(PointValues(vtp, "s").size(), n) << name;
    EXPECT_EQ(PointValues(vtp, "md"), PointValues(vtp, "s")) << name;  // no well
    EXPECT_EQ(PointValues(vtp, "displacement", 3).size(), 3 * n) << name;
    EXPECT_EQ(PointValues(vtp, "bending_moment").size(), n) << name;
  }
  // The last frame's points: the stations at final_q.
  const std::vector<double> last_points = FindArray(Element(frames.back(), "Points")).values;
  const std::vector<double> last_offset = PointValues(frames.back(), "lateral_offset");
  for (std::size_t i = 0; i < n; ++i) {
    for (int k = 0; k < 3; ++k) {
      ExpectRelativelyNear(last_points[3 * i + k], at_end[i].position[k], "station " + std::to_string(i) + " position");
    }
    ExpectRelativelyNear(last_offset[i], at_end[i].lateral_offset, "station " + std::to_string(i) + " lateral_offset");
  }
  // The first frame: the released deflection, P L³ / (3 E I) at the tip, the moment P L at the root.
  const double length = 200 * kIn;
  const double second_moment = kPi * std::pow(3 * kIn, 4) / 64.0;
  const double deflection = 100.0 * std::pow(length, 3) / (3.0 * 2.1e11 * second_moment);
  EXPECT_NEAR(PointValues(frames.front(), "lateral_offset").back(), deflection, 2e-3 * deflection);
  EXPECT_NEAR(PointValues(frames.front(), "bending_moment").front(), 100.0 * length, 0.02 * 100.0 * length);
  // The tip has moved between the first and the last frame.
  EXPECT_GT(std::abs(PointValues(frames.front(), "lateral_offset").back() - last_offset.back()), 1e-3);

  // A run without frames writes none.
  analyses::TransientResult none = result;
  none.frame_times.clear();
  none.frame_q.clear();
  ResultFiles no_files = FilesIn("transient-no-frames");
  AddTransientVtk(c, moving, none, no_files);
  const fs::path empty = Commit(no_files);
  EXPECT_FALSE(fs::exists(empty / "transient.pvd"));
  EXPECT_FALSE(fs::exists(empty / "string_0000.vtp"));
}

}  // namespace vtk_files_test
}  // namespace drillflex::io
