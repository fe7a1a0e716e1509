#include "io/xdmf.hpp"

#include <sstream>

#include "io/schema_reader.hpp"

namespace suspend::io {

namespace {

std::string data_item(const std::string& h5, const SnapshotInfo& s, const std::string& dataset,
                      const std::string& dims, bool integer = false) {
  return std::string("<DataItem Dimensions=\"") + dims + "\" NumberType=\"" + (integer ? "Int" : "Float") +
         "\" Precision=\"8\" Format=\"HDF\">" + h5 + ":/" + s.group + "/" + dataset + "</DataItem>";
}

std::string attribute(const std::string& name, const std::string& type, const std::string& center,
                      const std::string& item) {
  return "        <Attribute Name=\"" + name + "\" AttributeType=\"" + type + "\" Center=\"" + center + "\">\n          " +
         item + "\n        </Attribute>\n";
}

// Time is the strain (the axis rheologists read); the physical time in units of 1/gammadot_ref rides along.
std::string grid_head(const std::string& name, const SnapshotInfo& s) {
  return "      <Grid Name=\"" + name + "\" GridType=\"Uniform\">\n        <Time Value=\"" + exact(s.strain) +
         "\"/>\n        <Information Name=\"time\" Value=\"" + exact(s.time) + "\"/>\n";
}

}  // namespace

std::string xdmf_text(const std::string& h5, const std::vector<SnapshotInfo>& snapshots) {
  std::ostringstream x;
  x << "<?xml version=\"1.0\" ?>\n"
    << "<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n"
    << "<Xdmf Version=\"3.0\">\n  <Domain>\n";
  x << "    <Grid Name=\"particles\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  for (const SnapshotInfo& s : snapshots) {
    const std::string n = std::to_string(s.particles);
    x << grid_head(s.group, s)
      << "        <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"" << n << "\" NodesPerElement=\"1\"/>\n"
      << "        <Geometry GeometryType=\"XYZ\">\n          " << data_item(h5, s, "position", n + " 3")
      << "\n        </Geometry>\n"
      << attribute("radius", "Scalar", "Node", data_item(h5, s, "radius", n))
      << attribute("species", "Scalar", "Node", data_item(h5, s, "species", n, true))
      << attribute("velocity", "Vector", "Node", data_item(h5, s, "velocity", n + " 3"))
      << attribute("angular_velocity", "Vector", "Node", data_item(h5, s, "angular_velocity", n + " 3"))
      << "      </Grid>\n";
  }
  x << "    </Grid>\n";
  // The contact network: a line per contact from r_i to r_i + d (minimum image), its forces as cell data.
  x << "    <Grid Name=\"contacts\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  for (const SnapshotInfo& s : snapshots) {
    if (!s.segments || s.contacts == 0) continue;
    const std::string m = std::to_string(s.contacts), nodes = std::to_string(2 * s.contacts);
    x << grid_head(s.group, s) << "        <Topology TopologyType=\"Polyline\" NumberOfElements=\"" << m
      << "\" NodesPerElement=\"2\">\n          " << data_item(h5, s, "contact_segment_nodes", m + " 2", true)
      << "\n        </Topology>\n"
      << "        <Geometry GeometryType=\"XYZ\">\n          " << data_item(h5, s, "contact_segments", nodes + " 3")
      << "\n        </Geometry>\n"
      << attribute("contact_force", "Vector", "Cell", data_item(h5, s, "contact_force", m + " 3"))
      << attribute("contact_normal_force", "Scalar", "Cell", data_item(h5, s, "contact_normal_force", m))
      << attribute("contact_tangential_force", "Vector", "Cell", data_item(h5, s, "contact_tangential_force", m + " 3"))
      << attribute("contact_gap", "Scalar", "Cell", data_item(h5, s, "contact_gap", m))
      << attribute("contact_sliding", "Scalar", "Cell", data_item(h5, s, "contact_sliding", m, true))
      << "      </Grid>\n";
  }
  x << "    </Grid>\n";
  // The periodic cell: a hexahedron whose top face (y = L_y) is shifted by the Lees-Edwards offset.
  x << "    <Grid Name=\"box\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  for (const SnapshotInfo& s : snapshots) {
    const double lx = s.box.x(), ly = s.box.y(), lz = s.box.z(), o = s.shear_offset;
    const double v[8][3] = {{0, 0, 0},      {lx, 0, 0},      {lx, 0, lz},      {0, 0, lz},
                            {o, ly, 0},     {lx + o, ly, 0}, {lx + o, ly, lz}, {o, ly, lz}};
    x << grid_head(s.group, s)
      << "        <Topology TopologyType=\"Hexahedron\" NumberOfElements=\"1\">\n"
      << "          <DataItem Dimensions=\"1 8\" NumberType=\"Int\" Format=\"XML\">0 1 2 3 4 5 6 7</DataItem>\n"
      << "        </Topology>\n        <Geometry GeometryType=\"XYZ\">\n"
      << "          <DataItem Dimensions=\"8 3\" NumberType=\"Float\" Precision=\"8\" Format=\"XML\">";
    for (const auto& p : v) x << exact(p[0]) << ' ' << exact(p[1]) << ' ' << exact(p[2]) << ' ';
    x << "</DataItem>\n        </Geometry>\n      </Grid>\n";
  }
  x << "    </Grid>\n  </Domain>\n</Xdmf>\n";
  return x.str();
}

}  // namespace suspend::io
