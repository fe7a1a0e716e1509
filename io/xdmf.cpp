#include "io/xdmf.hpp"

#include <sstream>

#include "io/schema_reader.hpp"

namespace suspend::io {

std::string xdmf_text(const std::string& h5, const std::vector<SnapshotInfo>& snapshots) {
  std::ostringstream x;
  x << "<?xml version=\"1.0\" ?>\n"
    << "<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n"
    << "<Xdmf Version=\"3.0\">\n  <Domain>\n"
    << "    <Grid Name=\"particles\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  for (const SnapshotInfo& s : snapshots) {
    const std::string n = std::to_string(s.particles);
    auto item = [&](const std::string& dataset, const std::string& dims) {
      return "<DataItem Dimensions=\"" + dims + "\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">" + h5 +
             ":/" + s.group + "/" + dataset + "</DataItem>";
    };
    x << "      <Grid Name=\"" << s.group << "\" GridType=\"Uniform\">\n"
      << "        <Time Value=\"" << exact(s.time) << "\"/>\n"
      << "        <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"" << n << "\" NodesPerElement=\"1\"/>\n"
      << "        <Geometry GeometryType=\"XYZ\">\n          " << item("position", n + " 3") << "\n        </Geometry>\n"
      << "        <Attribute Name=\"radius\" AttributeType=\"Scalar\" Center=\"Node\">\n          "
      << item("radius", n) << "\n        </Attribute>\n"
      << "        <Attribute Name=\"velocity\" AttributeType=\"Vector\" Center=\"Node\">\n          "
      << item("velocity", n + " 3") << "\n        </Attribute>\n"
      << "        <Attribute Name=\"angular_velocity\" AttributeType=\"Vector\" Center=\"Node\">\n          "
      << item("angular_velocity", n + " 3") << "\n        </Attribute>\n"
      << "      </Grid>\n";
  }
  x << "    </Grid>\n  </Domain>\n</Xdmf>\n";
  return x.str();
}

}  // namespace suspend::io
