#include "io/XdmfSeries.hpp"

#include <filesystem>
#include <stdexcept>
#include <iomanip>
#include <sstream>

namespace ondine {

std::string xdmf_point_series(const std::string& collection, const std::string& grid, const std::vector<XdmfPointSet>& sets) {
  std::ostringstream x;
  x << "<?xml version=\"1.0\" ?>\n<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n<Xdmf Version=\"2.0\">\n <Domain>\n"
    << "  <Grid Name=\"" << collection << "\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  x << std::setprecision(17);
  for (const XdmfPointSet& e : sets) {
    x << "   <Grid Name=\"" << grid << "\" GridType=\"Uniform\">\n"
      << "    <Time Value=\"" << e.time << "\"/>\n"
      << "    <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"" << e.points << "\"/>\n"
      << "    <Geometry GeometryType=\"XYZ\">\n"
      << "     <DataItem Dimensions=\"" << e.points << " 3\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">"
      << e.file << ":/position</DataItem>\n    </Geometry>\n";
    for (const auto& [name, comps] : e.fields) {
      if (name == "position") continue;
      x << "    <Attribute Name=\"" << name << "\" AttributeType=\"" << (comps == 3 ? "Vector" : "Scalar")
        << "\" Center=\"Node\">\n     <DataItem Dimensions=\"" << e.points << (comps == 3 ? " 3" : "")
        << "\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">" << e.file << ":/" << name
        << "</DataItem>\n    </Attribute>\n";
    }
    x << "   </Grid>\n";
  }
  x << "  </Grid>\n </Domain>\n</Xdmf>\n";
  return x.str();
}

void remove_numbered_files(const std::string& dir, const std::string& prefix, std::size_t first) {
  namespace fs = std::filesystem;
  if (!fs::is_directory(dir)) return;
  for (const auto& e : fs::directory_iterator(dir)) {
    const std::string f = e.path().filename().string();
    if (f.size() != prefix.size() + 9 || f.compare(0, prefix.size(), prefix) != 0 || f.compare(f.size() - 3, 3, ".h5") != 0) continue;
    const std::string digits = f.substr(prefix.size(), 6);
    if (digits.find_first_not_of("0123456789") != std::string::npos) continue;
    std::error_code ec;
    if (std::stoul(digits) >= first && !fs::remove(e.path(), ec) && ec)
      throw std::runtime_error("cannot remove " + e.path().string() + ", a snapshot of an earlier run in the output folder: " + ec.message());
  }
}

}  // namespace ondine
