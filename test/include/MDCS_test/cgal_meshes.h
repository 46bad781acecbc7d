// Access to CGAL's demo meshes (Debian's libcgal-demo, unpacked by the top-level CMakeLists into the build
// tree and passed as the macro MDCS_CGAL_MESH_DIR, "" when unavailable), and a loader for any FaceGraph.
#ifndef MDCS_TEST_CGAL_MESHES_H
#define MDCS_TEST_CGAL_MESHES_H

#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <fstream>
#include <string>

#ifndef MDCS_CGAL_MESH_DIR
#define MDCS_CGAL_MESH_DIR ""
#endif

namespace MDCS_test {

// The folder of CGAL's demo meshes, "" when unknown.
inline std::string cgal_demo_mesh_dir()
{
  return std::string(MDCS_CGAL_MESH_DIR);
}

// The full path of CGAL's demo mesh `name` (e.g. "elephant.off") if the file exists and is readable, else "".
inline std::string cgal_demo_mesh(const std::string& name)
{
  const std::string dir = cgal_demo_mesh_dir();
  if(dir.empty() || name.empty())
    return std::string();
  const std::string path = (dir.back() == '/' ? dir : dir + "/") + name;
  std::ifstream in(path.c_str());
  return in.good() ? path : std::string();
}

// Reads a polygon mesh (OFF, OBJ, PLY, STL, ...) into `m` (cleared first). Returns false if the path is empty,
// the file cannot be read, or the result is empty.
template <class Mesh>
bool read_mesh(const std::string& path, Mesh& m)
{
  if(path.empty())
    return false;
  clear(m);
  if(!CGAL::IO::read_polygon_mesh(path, m))
    return false;
  return num_faces(m) > 0;
}

} // namespace MDCS_test

#endif // MDCS_TEST_CGAL_MESHES_H
