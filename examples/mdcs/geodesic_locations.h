// The sources and targets of `mdcs geodesics` (cmd_geodesics.h): vertex indices or face points f:FACE:B0:B1:B2
// on the command line, checked against the mesh, and their points and descriptions.
#ifndef MDCS_CLI_GEODESIC_LOCATIONS_H
#define MDCS_CLI_GEODESIC_LOCATIONS_H

#include "cli_common.h"
#include "geodesic_soup.h"
#include "mesh_input.h"

#include <array>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

namespace mdcs_cli {

// A source or target: a vertex, or a point of a face given by the weights of its corners in listing order.
struct Geo_location
{
  bool at_vertex = true;
  std::size_t index = 0;                       // vertex or face index
  std::array<double, 3> weights = {{1, 0, 0}}; // faces: corners in listing order, normalised
  std::string text;                            // as given on the command line
};

inline std::vector<Geo_location> parse_geo_locations(const std::string& spec, const char* option)
{
  std::vector<Geo_location> result;
  const std::string what = std::string("--") + option;
  auto bad = [&](const std::string& item, const std::string& why) {
    return Usage_error(what + ": '" + item + "' " + why + " (expected vertex indices such as 0,17 or face points f:FACE:B0:B1:B2)");
  };
  auto index = [&](const std::string& item, const std::string& s) {
    if(s.empty() || s.find_first_not_of("0123456789") != std::string::npos) throw bad(item, "is not a non-negative integer");
    try {
      return std::size_t(std::stoull(s));
    } catch(const std::exception&) {
      throw bad(item, "is too large");
    }
  };
  std::stringstream items(spec);
  std::string item;
  while(std::getline(items, item, ',')) {
    if(item.empty()) throw bad(spec, "has an empty item");
    Geo_location loc;
    loc.text = item;
    if(item[0] == 'f' || item[0] == 'F') {
      std::vector<std::string> parts;
      std::stringstream fields(item);
      std::string field;
      while(std::getline(fields, field, ':')) parts.push_back(field);
      if(parts.size() != 5 || (parts[0] != "f" && parts[0] != "F")) throw bad(item, "is not f:FACE:B0:B1:B2");
      loc.at_vertex = false;
      loc.index = index(item, parts[1]);
      double sum = 0;
      for(int k = 0; k < 3; ++k) {
        char* end = nullptr;
        const double w = std::strtod(parts[std::size_t(k) + 2].c_str(), &end);
        if(parts[std::size_t(k) + 2].empty() || *end != '\0' || !std::isfinite(w) || w < 0)
          throw bad(item, "has a weight that is not a finite number >= 0");
        loc.weights[std::size_t(k)] = w;
        sum += w;
      }
      if(!(sum > 0)) throw bad(item, "has weights that sum to 0");
      for(double& w : loc.weights) w /= sum;
    } else {
      loc.index = index(item, item);
    }
    result.push_back(loc);
  }
  if(!spec.empty() && spec.back() == ',') throw bad(spec, "ends with a comma");
  return result;
}

// A Geo_mesh or a Geo_soup (geodesic_soup.h).
template <class Surface>
void validate_geo_locations(const Surface& m, const std::vector<Geo_location>& locations, const char* option)
{
  const std::size_t nv = geo_vertex_count(m), nf = geo_face_count(m);
  for(const Geo_location& loc : locations) {
    if(loc.at_vertex) {
      if(loc.index >= nv)
        throw Usage_error(std::string("--") + option + ": vertex " + std::to_string(loc.index) + " does not exist (the mesh has " +
                          std::to_string(nv) + " vertices, 0 to " + std::to_string(nv - 1) + ")");
      if(geo_is_isolated(m, loc.index))
        throw Usage_error(std::string("--") + option + ": vertex " + std::to_string(loc.index) + " has no incident face");
    } else if(loc.index >= nf) {
      throw Usage_error(std::string("--") + option + ": face " + std::to_string(loc.index) + " does not exist (the mesh has " +
                        std::to_string(nf) + " faces, 0 to " + std::to_string(nf - 1) + ")");
    }
  }
}

// The corners of a triangle in listing order (the order of distances.ply, and of the file for valid meshes).
inline std::array<Geo_mesh::Vertex_index, 3> face_corners(const Geo_mesh& m, Geo_mesh::Face_index f)
{
  const auto h = m.halfedge(f);
  return {{m.target(h), m.target(m.next(h)), m.target(m.next(m.next(h)))}};
}

// Face_location coordinates refer to source(h), target(h), target(next(h)), that is corners 2, 0, 1.
inline std::array<double, 3> face_location_weights(const Geo_location& loc)
{
  return {{loc.weights[2], loc.weights[0], loc.weights[1]}};
}

template <class Surface>
Geo_point location_point(const Surface& m, const Geo_location& loc)
{
  if(loc.at_vertex) return geo_vertex_point(m, loc.index);
  const auto c = geo_triangle(m, loc.index);
  double x = 0, y = 0, z = 0;
  for(int k = 0; k < 3; ++k) {
    const Geo_point& p = geo_vertex_point(m, c[std::size_t(k)]);
    x += loc.weights[std::size_t(k)] * p.x();
    y += loc.weights[std::size_t(k)] * p.y();
    z += loc.weights[std::size_t(k)] * p.z();
  }
  return Geo_point(x, y, z);
}

inline std::string describe_location(const Geo_location& loc)
{
  if(loc.at_vertex) return "vertex " + std::to_string(loc.index);
  std::ostringstream s;
  s << "face " << loc.index << " (" << std::setprecision(3) << loc.weights[0] << ", " << loc.weights[1] << ", " << loc.weights[2] << ")";
  return s.str();
}

} // namespace mdcs_cli

#endif // MDCS_CLI_GEODESIC_LOCATIONS_H
