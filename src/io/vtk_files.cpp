#include "io/vtk_files.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "analyses/wall_offsets.hpp"
#include "core/error.hpp"
#include "io/analysis_results.hpp"
#include "model/wall_contact.hpp"
#include "well/hole.hpp"
#include "well/trajectory.hpp"

namespace drillflex::io {
namespace {

// ---- The XML: a PolyData of points, point data and either one polyline or one vertex per point ----

// A named array of point data: `components` values per point, point after point.
struct PointArray {
  std::string name;
  int components = 1;
  bool integer = false;  // Int32 (written rounded), else Float64
  std::vector<double> values;
};

enum class Cells { kOnePolyline, kVertices };

struct PolyData {
  std::vector<Vec3> points;
  std::vector<PointArray> arrays;
  std::string active_scalars;  // the name of an array, or ""
  std::string active_vectors;
};

// Writes numbers the way VTK's ASCII reader takes them: the shortest text that reads back as the same
// double; a non-finite value as 0 (counted, the file says how many), −0 as 0.
class NumberWriter {
 public:
  void Append(std::string& text, double value) {
    if (!std::isfinite(value)) {
      ++non_finite_;
      value = 0.0;
    }
    if (value == 0.0) value = 0.0;  // −0 → +0
    fmt::format_to(std::back_inserter(text), "{}", value);
  }
  int non_finite() const { return non_finite_; }

 private:
  int non_finite_ = 0;
};

// The values of a DataArray, a few to a line (a line per point for vectors).
void AppendValues(std::string& text, const std::vector<double>& values, std::size_t per_line, bool integer,
                  NumberWriter& numbers) {
  for (std::size_t i = 0; i < values.size(); ++i) {
    text.append(i % per_line == 0 ? "\n          " : " ");
    if (integer) {
      fmt::format_to(std::back_inserter(text), "{}", std::isfinite(values[i]) ? std::lround(values[i]) : 0L);
    } else {
      numbers.Append(text, values[i]);
    }
  }
  text.append("\n        ");
}

void AppendDataArray(std::string& text, const PointArray& array, NumberWriter& numbers) {
  text.append(fmt::format("        <DataArray type=\"{}\" Name=\"{}\"", array.integer ? "Int32" : "Float64", array.name));
  if (array.components != 1) text.append(fmt::format(" NumberOfComponents=\"{}\"", array.components));
  text.append(" format=\"ascii\">");
  const std::size_t per_line = array.components == 1 ? 6 : static_cast<std::size_t>(array.components);
  AppendValues(text, array.values, per_line, array.integer, numbers);
  text.append("</DataArray>\n");
}

// Cells of point indices: `connectivity` and `offsets` (the end of each cell in connectivity; no
// polyline without points).
void AppendCells(std::string& text, const char* tag, std::size_t points, Cells cells) {
  std::vector<double> connectivity(points), offsets;
  for (std::size_t i = 0; i < points; ++i) {
    connectivity[i] = static_cast<double>(i);
    if (cells == Cells::kVertices) offsets.push_back(static_cast<double>(i + 1));
  }
  if (cells == Cells::kOnePolyline && points > 0) offsets.push_back(static_cast<double>(points));
  NumberWriter numbers;  // integers only
  text.append(fmt::format("      <{}>\n", tag));
  AppendDataArray(text, {"connectivity", 1, true, connectivity}, numbers);
  AppendDataArray(text, {"offsets", 1, true, offsets}, numbers);
  text.append(fmt::format("      </{}>\n", tag));
}

std::string ToVtkXml(const PolyData& data, Cells cells) {
  const std::size_t n = data.points.size();
  const bool polyline = cells == Cells::kOnePolyline;
  NumberWriter numbers;
  std::string body;
  body.append("      <PointData");
  if (!data.active_scalars.empty()) body.append(fmt::format(" Scalars=\"{}\"", data.active_scalars));
  if (!data.active_vectors.empty()) body.append(fmt::format(" Vectors=\"{}\"", data.active_vectors));
  body.append(">\n");
  for (const PointArray& array : data.arrays) AppendDataArray(body, array, numbers);
  body.append("      </PointData>\n      <Points>\n");
  PointArray points{"Points", 3, false, {}};
  points.values.reserve(3 * n);
  for (const Vec3& point : data.points) points.values.insert(points.values.end(), {point.x(), point.y(), point.z()});
  AppendDataArray(body, points, numbers);
  body.append("      </Points>\n");
  AppendCells(body, polyline ? "Lines" : "Verts", n, cells);

  std::string text = "<?xml version=\"1.0\"?>\n";
  text.append("<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\">\n");
  if (numbers.non_finite() > 0) {
    text.append(fmt::format("  <!-- {} values that were not finite written as 0 -->\n", numbers.non_finite()));
  }
  text.append("  <PolyData>\n");
  const std::size_t verts = polyline ? 0 : n;
  const std::size_t lines = polyline && n > 0 ? 1 : 0;
  text.append(fmt::format("    <Piece NumberOfPoints=\"{}\" NumberOfVerts=\"{}\" NumberOfLines=\"{}\" "
                          "NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n",
                          n, verts, lines));
  text.append(body);
  text.append("    </Piece>\n  </PolyData>\n</VTKFile>\n");
  return text;
}

// Point data from one value (or vector) per item.
template <typename Item, typename Get>
PointArray Scalars(std::string name, const std::vector<Item>& items, Get get) {
  PointArray array{std::move(name), 1, false, {}};
  array.values.reserve(items.size());
  for (const Item& item : items) array.values.push_back(get(item));
  return array;
}

template <typename Item, typename Get>
PointArray Integers(std::string name, const std::vector<Item>& items, Get get) {
  PointArray array = Scalars(std::move(name), items, get);
  array.integer = true;
  return array;
}

template <typename Item, typename Get>
PointArray Vectors(std::string name, const std::vector<Item>& items, Get get) {
  PointArray array{std::move(name), 3, false, {}};
  array.values.reserve(3 * items.size());
  for (const Item& item : items) {
    const Vec3 v = get(item);
    array.values.insert(array.values.end(), {v.x(), v.y(), v.z()});
  }
  return array;
}

// ---- The model's wells and contact circles ----

// Two stations closer than this along the string are the same node (as analyses/wall_offsets.cpp).
constexpr double kSameStationTolerance = 1e-6;  // m

struct ContactCircleAt {
  double s = 0.0;       // m from the bit
  double radius = 0.0;  // R_c, m
};

// The model's wall-contact circles by station, ascending in s.
std::vector<ContactCircleAt> ContactCirclesByStation(const model::BuiltModel& built) {
  std::vector<ContactCircleAt> circles;
  for (const auto handle : built.contacts) {
    const model::WallContactElement& contact = built.Get(handle);
    const model::Body& body = *contact.bodies()[0];
    circles.push_back({body.NodeS(contact.node()), contact.parameters().contact_radius});
  }
  std::sort(circles.begin(), circles.end(), [](const auto& a, const auto& b) { return a.s < b.s; });
  return circles;
}

// The radius of the wall-contact circle at a station (model/contact_circles.hpp: a blade's or a tool
// joint's at the node nearest it, the body's elsewhere); without one (the bit's node, no well) half
// the diameter that touches the wall there.
double ContactRadiusAt(const Case& c, const std::vector<ContactCircleAt>& circles, double s) {
  const auto at = std::lower_bound(circles.begin(), circles.end(), s - kSameStationTolerance,
                                   [](const ContactCircleAt& circle, double value) { return circle.s < value; });
  if (at != circles.end() && std::abs(at->s - s) <= kSameStationTolerance) return at->radius;
  return c.input.string.components.empty() ? 0.0 : 0.5 * model::ContactDiameterAt(c.input.string, s);
}

// Half the body OD at a station; at a connection the component's below (model::ComponentAt).
double OuterRadiusAt(const Case& c, double s) {
  return c.input.string.components.empty() ? 0.0 : 0.5 * model::ComponentAt(c.input.string, s).outer_diameter;
}

// ---- string.vtp (a static result's, and each frame of a transient's) ----

double NodeMd(const Case& c, const analyses::StaticNodeResult& node) {
  return node.has_wall ? node.md : StationMd(c, node.s);
}

std::string StringVtp(const Case& c, const model::BuiltModel& built, const std::vector<analyses::StaticNodeResult>& nodes) {
  using Node = analyses::StaticNodeResult;
  const bool in_hole = std::any_of(nodes.begin(), nodes.end(), [](const Node& node) { return node.has_wall; });
  const std::vector<ContactCircleAt> circles = ContactCirclesByStation(built);
  PolyData data;
  for (const Node& node : nodes) data.points.push_back(node.position);
  data.arrays = {
      Scalars("s", nodes, [](const Node& n) { return n.s; }),
      Scalars("md", nodes, [&](const Node& n) { return NodeMd(c, n); }),
      Vectors("displacement", nodes, [](const Node& n) { return n.displacement; }),
      Vectors("rotation", nodes, [](const Node& n) { return n.rotation; }),
      Scalars("lateral_offset", nodes, [](const Node& n) { return n.lateral_offset; }),
      Scalars("axial_force", nodes, [](const Node& n) { return n.axial_force; }),
      Scalars("torque", nodes, [](const Node& n) { return n.torque; }),
      Scalars("shear_force", nodes, [](const Node& n) { return n.shear_force; }),
      Scalars("bending_moment", nodes, [](const Node& n) { return n.bending_moment; }),
      Scalars("bending_stress", nodes, [](const Node& n) { return n.bending_stress; }),
      Scalars("von_mises_stress", nodes, [](const Node& n) { return n.von_mises_stress; }),
  };
  if (in_hole) {
    data.arrays.push_back(Scalars("hole_offset", nodes, [](const Node& n) { return n.hole_offset; }));
    data.arrays.push_back(Scalars("offset_high_side_angle", nodes, [](const Node& n) { return n.offset_high_side_angle; }));
    data.arrays.push_back(Scalars("clearance", nodes, [](const Node& n) { return n.clearance; }));
    data.arrays.push_back(Scalars("hole_diameter", nodes, [](const Node& n) { return n.hole_diameter; }));
  }
  data.arrays.push_back(Scalars("outer_radius", nodes, [&](const Node& n) { return OuterRadiusAt(c, n.s); }));
  data.arrays.push_back(
      Scalars("contact_radius", nodes, [&](const Node& n) { return ContactRadiusAt(c, circles, n.s); }));
  data.active_scalars = "outer_radius";
  data.active_vectors = "displacement";
  return ToVtkXml(data, Cells::kOnePolyline);
}

// ---- well.vtp ----

// The largest sag of a chord below its arc allowed between two points of the drawn hole axis: a
// tenth of a millimetre, well below the clearance of a stabilizer's blades (about a millimetre).
constexpr double kMaxChordSag = 1e-4;  // m
// At a step of the hole diameter, the second point is this far below the first (both diameters show).
constexpr double kStepLength = 1e-3;   // m

// The MDs at which the hole's axis is drawn over [top, bottom]: both ends, the survey stations (the
// arcs' ends), the hole sections' ends (and just below a step), the string's stations, and between
// them as many points as keep the chords within kMaxChordSag of the arc (sag = κ ℓ²/8).
std::vector<double> WellMds(const model::Wellbore& wellbore, double top, double bottom, const std::vector<double>& node_mds) {
  std::vector<double> mds{top, bottom};
  auto add = [&](double md) {
    if (md > top && md < bottom) mds.push_back(md);
  };
  for (const well::SurveyStation& station : wellbore.trajectory.stations()) add(station.md);
  for (const well::HoleSection& section : wellbore.hole.sections()) {
    if (!section.to_md) continue;
    add(*section.to_md);
    add(*section.to_md + kStepLength);
  }
  for (const double md : node_mds) add(md);
  std::sort(mds.begin(), mds.end());
  mds.erase(std::unique(mds.begin(), mds.end(), [](double a, double b) { return b - a <= kSameStationTolerance; }),
            mds.end());
  std::vector<double> sampled;
  for (std::size_t i = 0; i + 1 < mds.size(); ++i) {
    // One arc between two consecutive MDs (the survey stations are among them): κ at the middle.
    const double length = mds[i + 1] - mds[i];
    const double curvature = wellbore.trajectory.Curvature(mds[i] + 0.5 * length).norm();
    const double longest = curvature > 0.0 ? std::sqrt(8.0 * kMaxChordSag / curvature) : length;
    const int pieces = std::max(1, static_cast<int>(std::ceil(length / longest)));
    for (int k = 0; k < pieces; ++k) sampled.push_back(mds[i] + length * k / pieces);
  }
  sampled.push_back(mds.back());
  return sampled;
}

// The stations' MDs that are numbers.
std::vector<double> FiniteNodeMds(const Case& c, const std::vector<analyses::StaticNodeResult>& nodes) {
  std::vector<double> mds;
  for (const auto& node : nodes) {
    if (std::isfinite(NodeMd(c, node))) mds.push_back(NodeMd(c, node));
  }
  return mds;
}

// `node_mds`: FiniteNodeMds, not empty.
std::string WellVtp(const model::Wellbore& wellbore, const std::vector<double>& node_mds) {
  const auto [shallowest, deepest] = std::minmax_element(node_mds.begin(), node_mds.end());
  // Above the survey's first station the trajectory has no place to draw.
  const double top = std::max(*shallowest, wellbore.trajectory.start_md());
  const double bottom = std::max(*deepest, top);
  const std::vector<double> mds = WellMds(wellbore, top, bottom, node_mds);
  const auto& trajectory = wellbore.trajectory;
  const auto& hole = wellbore.hole;
  PolyData data;
  for (const double md : mds) data.points.push_back(trajectory.Position(md));
  data.arrays = {
      Scalars("md", mds, [](double md) { return md; }),
      Scalars("hole_diameter", mds, [&](double md) { return hole.Diameter(md); }),
      Scalars("hole_radius", mds, [&](double md) { return 0.5 * hole.Diameter(md); }),
      Scalars("inclination", mds, [&](double md) { return trajectory.Inclination(md); }),
      Scalars("azimuth", mds, [&](double md) { return trajectory.Azimuth(md); }),
  };
  data.active_scalars = "hole_radius";
  return ToVtkXml(data, Cells::kOnePolyline);
}

// ---- contacts.vtp ----

std::string ContactsVtp(const std::vector<analyses::ContactReport>& contacts) {
  using Contact = analyses::ContactReport;
  // The wall pushes the string along −n (n: from the hole axis toward the contact).
  auto on_string = [](const Contact& contact) { return Vec3(-contact.normal); };
  PolyData data;
  for (const Contact& contact : contacts) data.points.push_back(contact.contact_point);
  data.arrays = {
      Scalars("s", contacts, [](const Contact& contact) { return contact.s; }),
      Scalars("md", contacts, [](const Contact& contact) { return contact.md; }),
      Integers("component", contacts, [](const Contact& contact) { return static_cast<double>(contact.component); }),
      Scalars("normal_force", contacts, [](const Contact& contact) { return contact.normal_force; }),
      Scalars("friction_force", contacts, [](const Contact& contact) { return contact.friction_force; }),
      Vectors("normal", contacts, on_string),
      Vectors("normal_force_vector", contacts,
              [&](const Contact& contact) { return Vec3(contact.normal_force * on_string(contact)); }),
  };
  data.active_scalars = "normal_force";
  data.active_vectors = "normal_force_vector";
  return ToVtkXml(data, Cells::kVertices);
}

// ---- transient.pvd ----

// The collection of a transient's frames: one data set per file, at its time (s).
std::string TransientPvd(const std::vector<double>& times, const std::vector<std::string>& files) {
  NumberWriter numbers;
  std::string text = "<?xml version=\"1.0\"?>\n";
  text.append("<VTKFile type=\"Collection\" version=\"1.0\" byte_order=\"LittleEndian\">\n  <Collection>\n");
  for (std::size_t i = 0; i < files.size(); ++i) {
    text.append("    <DataSet timestep=\"");
    numbers.Append(text, times[i]);
    text.append(fmt::format("\" group=\"\" part=\"0\" file=\"{}\"/>\n", files[i]));
  }
  text.append("  </Collection>\n</VTKFile>\n");
  return text;
}

}  // namespace

void AddStaticVtk(const Case& c, const model::BuiltModel& built, const analyses::StaticResult& result,
                  ResultFiles& files) {
  files.Add("string.vtp", StringVtp(c, built, result.nodes));
  const std::vector<double> node_mds = FiniteNodeMds(c, result.nodes);
  // The case's well, the one its model was built in (its wall contacts share it).
  if (c.input.well && !node_mds.empty()) files.Add("well.vtp", WellVtp(*c.input.well, node_mds));
  if (!result.contacts.empty()) files.Add("contacts.vtp", ContactsVtp(result.contacts));
}

void AddTransientVtk(const Case& c, const model::BuiltModel& built, const analyses::TransientResult& result,
                     ResultFiles& files) {
  if (result.frame_times.size() != result.frame_q.size()) {
    throw LogicError("AddTransientVtk: the frames' times and states differ in number");
  }
  std::vector<std::string> names;
  for (std::size_t i = 0; i < result.frame_q.size(); ++i) {
    const VecX& q = result.frame_q[i];
    if (q.size() != built.system.num_positions()) throw LogicError("AddTransientVtk: a frame is not the model's state");
    std::vector<analyses::StaticNodeResult> nodes = analyses::StaticNodeResults(built, q, 1.0);
    analyses::AddWallOffsets(built, q, nodes);
    names.push_back(fmt::format("string_{:04}.vtp", i));
    files.Add(names.back(), StringVtp(c, built, nodes));
  }
  if (!names.empty()) files.Add("transient.pvd", TransientPvd(result.frame_times, names));
}

}  // namespace drillflex::io
