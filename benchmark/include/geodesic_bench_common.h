// Shared by the geodesic benchmarks (bench_exact_geodesics, bench_approximate_geodesics): the meshes (CGAL's demo
// meshes, their Loop subdivisions, every mesh of an extra folder), loading and repair, the common command-line
// options, and the measurement of one run of a method in a forked child process (time limit, address-space
// limit, peak resident set size of the child).
#ifndef MDCS_GEODESIC_BENCH_COMMON_H
#define MDCS_GEODESIC_BENCH_COMMON_H

#include <mdcs_bench.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/repair.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/subdivision_method_3.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <malloc.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#ifndef MDCS_CGAL_MESH_DIR
#define MDCS_CGAL_MESH_DIR ""
#endif

namespace geodesic_bench {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef Mesh::Vertex_index Vertex;

const double inf = std::numeric_limits<double>::infinity();
const double nan_ = std::numeric_limits<double>::quiet_NaN();

using mdcs_bench::fmt;

// ---- running one method in a forked child ------------------------------------------------------------------

inline bool write_all(int fd, const void* data, std::size_t size)
{
  const char* p = static_cast<const char*>(data);
  while(size > 0) {
    const ssize_t w = ::write(fd, p, size);
    if(w < 0 && errno == EINTR) continue;
    if(w <= 0) return false;
    p += w;
    size -= std::size_t(w);
  }
  return true;
}

inline bool read_all(int fd, void* data, std::size_t size)
{
  char* p = static_cast<char*>(data);
  while(size > 0) {
    const ssize_t r = ::read(fd, p, size);
    if(r < 0 && errno == EINTR) continue;
    if(r <= 0) return false;
    p += r;
    size -= std::size_t(r);
  }
  return true;
}

inline double status_field_mib(const char* field)
{
  std::ifstream in("/proc/self/status");
  std::string line;
  const std::size_t len = std::strlen(field);
  while(std::getline(in, line))
    if(line.compare(0, len, field) == 0)
      return std::stod(line.substr(len)) / 1024.0;
  return 0.0;
}

inline double mem_available_mib()
{
  std::ifstream in("/proc/meminfo");
  std::string line;
  while(std::getline(in, line))
    if(line.compare(0, 13, "MemAvailable:") == 0)
      return std::stod(line.substr(13)) / 1024.0;
  return 0.0;
}

// The outcome of one forked run. `Header` is a plain struct (copied through a pipe byte for byte) with at least
//   std::int32_t ok; double peak_mib; std::uint64_t number_of_distances; char error[512];
// and whatever else the program measures.
template <class Header>
struct Forked_result
{
  bool ok = false;
  std::string failure; // "crash (signal 11)", "timeout", "out of memory", an exception's message
  Header header;
  std::vector<double> distances;
};

// Runs `method(header, distances)` in a child process with a time limit (seconds, 0: none) and an address-space
// limit (MiB above what the child inherits, 0: none). The child's peak memory is its peak resident set size
// minus its resident set size when the method starts: what the parent shares with it (the input mesh) is not
// counted, everything the method allocates is.
template <class Header, class Method>
Forked_result<Header> run_forked(Method method, double timeout_s, double mem_limit_mib)
{
  Forked_result<Header> result;
  int fds[2];
  if(::pipe(fds) != 0) {
    result.failure = "pipe() failed";
    return result;
  }
  std::cout.flush();
  std::cerr.flush();
  std::fflush(nullptr);
  malloc_trim(0);
  const pid_t pid = ::fork();
  if(pid < 0) {
    ::close(fds[0]);
    ::close(fds[1]);
    result.failure = "fork() failed";
    return result;
  }
  if(pid == 0) { // ---- child
    ::close(fds[0]);
    if(mem_limit_mib > 0) {
      const double vm = status_field_mib("VmSize:");
      struct rlimit lim;
      lim.rlim_cur = lim.rlim_max = rlim_t((vm + mem_limit_mib) * 1024.0 * 1024.0);
      setrlimit(RLIMIT_AS, &lim);
    }
    if(timeout_s > 0) ::alarm(unsigned(std::ceil(timeout_s)));
    Header header;
    std::vector<double> distances;
    malloc_trim(0);
    const double baseline = mdcs_bench::current_rss_mib();
    mdcs_bench::reset_peak_rss(); // a fork starts with peak = current RSS anyway; this makes it explicit
    try {
      method(header, distances);
      header.ok = 1;
    } catch(const std::bad_alloc&) {
      std::snprintf(header.error, sizeof header.error, "out of memory (std::bad_alloc)");
    } catch(const std::exception& e) {
      std::snprintf(header.error, sizeof header.error, "exception: %s", e.what());
    } catch(...) {
      std::snprintf(header.error, sizeof header.error, "unknown exception");
    }
    header.peak_mib = std::max(0.0, mdcs_bench::peak_rss_mib() - baseline);
    header.number_of_distances = header.ok ? distances.size() : 0;
    bool good = write_all(fds[1], &header, sizeof header);
    if(good && header.number_of_distances)
      good = write_all(fds[1], distances.data(), distances.size() * sizeof(double));
    ::close(fds[1]);
    ::_exit(good ? 0 : 3);
  }
  // ---- parent
  ::close(fds[1]);
  bool got = read_all(fds[0], &result.header, sizeof result.header);
  if(got && result.header.number_of_distances) {
    result.distances.resize(std::size_t(result.header.number_of_distances));
    got = read_all(fds[0], result.distances.data(), result.distances.size() * sizeof(double));
  }
  ::close(fds[0]);
  int status = 0;
  while(::waitpid(pid, &status, 0) < 0 && errno == EINTR) {}
  if(WIFSIGNALED(status)) {
    const int sig = WTERMSIG(status);
    result.failure = sig == SIGALRM ? "timeout (> " + fmt(timeout_s, "%.0f") + " s)"
                   : sig == SIGKILL ? "killed (signal 9, out of memory?)"
                                    : "crash (signal " + std::to_string(sig) + ", " + strsignal(sig) + ")";
    return result;
  }
  if(!got) {
    result.failure = "child exited with status " + std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : -1) +
                     " without a result";
    return result;
  }
  if(!result.header.ok) {
    result.failure = result.header.error;
    return result;
  }
  result.ok = true;
  return result;
}

// A writable vertex property map into a std::vector<double>.
struct Distance_vector_map
{
  std::vector<double>* values;
  friend void put(const Distance_vector_map& m, Vertex v, double d) { (*m.values)[std::size_t(v)] = d; }
};

// ---- meshes ------------------------------------------------------------------------------------------------

struct Mesh_spec
{
  std::string name;
  std::string file;      // path of the file to read
  int loop_steps = 0;    // Loop subdivision steps applied after reading
};

inline std::size_t count_boundary_edges(const Mesh& mesh)
{
  return std::size_t(std::count_if(halfedges(mesh).begin(), halfedges(mesh).end(),
                                   [&](Mesh::Halfedge_index h) { return is_border(h, mesh); }));
}

inline std::size_t count_components(Mesh& mesh)
{
  auto fcc = mesh.add_property_map<Mesh::Face_index, std::size_t>("f:bench_cc", 0).first;
  const std::size_t components = CGAL::Polygon_mesh_processing::connected_components(mesh, fcc);
  mesh.remove_property_map(fcc);
  return components;
}

// Reads, triangulates, removes isolated vertices, subdivides; `message` lists what was done and the mesh's
// boundary edges and components (or why it failed).
inline bool load_mesh(const Mesh_spec& spec, Mesh& mesh, std::string& message)
{
  mesh.clear();
  if(!std::filesystem::exists(spec.file)) {
    message = "file not found: " + spec.file;
    return false;
  }
  if(!CGAL::IO::read_polygon_mesh(spec.file, mesh) || mesh.is_empty()) {
    message = "cannot read " + spec.file + " as a polygon mesh";
    return false;
  }
  std::ostringstream notes;
  if(!CGAL::is_triangle_mesh(mesh)) {
    CGAL::Polygon_mesh_processing::triangulate_faces(mesh);
    notes << "triangulated; ";
  }
  const std::size_t isolated = CGAL::Polygon_mesh_processing::remove_isolated_vertices(mesh);
  if(isolated) notes << "removed " << isolated << " isolated vertices; ";
  if(spec.loop_steps > 0)
    CGAL::Subdivision_method_3::Loop_subdivision(mesh, CGAL::parameters::number_of_iterations(spec.loop_steps));
  if(mesh.has_garbage()) mesh.collect_garbage();
  const std::size_t boundary = count_boundary_edges(mesh);
  const std::size_t components = count_components(mesh);
  if(boundary) notes << boundary << " boundary edges; ";
  if(components != 1) notes << components << " components; ";
  message = notes.str();
  if(message.size() >= 2) message.resize(message.size() - 2);
  return true;
}

inline double average_edge_length(const Mesh& mesh)
{
  double sum = 0;
  std::size_t n = 0;
  for(auto e : edges(mesh)) {
    sum += std::sqrt(CGAL::squared_distance(mesh.point(source(halfedge(e, mesh), mesh)),
                                            mesh.point(target(halfedge(e, mesh), mesh))));
    ++n;
  }
  return n ? sum / double(n) : 1.0;
}

inline std::vector<std::string> split(const std::string& s, char sep)
{
  std::vector<std::string> out;
  std::string item;
  std::istringstream in(s);
  while(std::getline(in, item, sep))
    if(!item.empty()) out.push_back(item);
  return out;
}

// Least-squares slope of log(y) against log(x), over the points with finite positive x and y.
inline double loglog_slope(const std::vector<std::pair<double, double>>& points, std::size_t& used)
{
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  used = 0;
  std::set<double> xs;
  for(const auto& p : points) {
    if(!(p.first > 0 && p.second > 0 && std::isfinite(p.first) && std::isfinite(p.second))) continue;
    const double x = std::log(p.first), y = std::log(p.second);
    sx += x; sy += y; sxx += x * x; sxy += x * y;
    ++used;
    xs.insert(p.first);
  }
  if(xs.size() < 2) return nan_;
  const double n = double(used);
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

// ---- common options ----------------------------------------------------------------------------------------

struct Common_options
{
  std::string mesh_dir = MDCS_CGAL_MESH_DIR;
  std::string extra_dir;
  std::string csv;
  std::vector<std::string> selected; // --meshes
  int runs = 3;
  double timeout_s = 1800;
  double mem_limit_mib = 0; // 0: 60% of the available memory
  bool list_only = false;

  // Consumes argv[i] (and its value) if it is a common option; returns false otherwise.
  bool parse(int argc, char** argv, int& i)
  {
    const std::string a = argv[i];
    const bool has_value = i + 1 < argc;
    if(a == "--meshes" && has_value) selected = split(argv[++i], ',');
    else if(a == "--runs" && has_value) runs = std::max(1, std::atoi(argv[++i]));
    else if(a == "--mesh-dir" && has_value) mesh_dir = argv[++i];
    else if(a == "--extra-dir" && has_value) extra_dir = argv[++i];
    else if(a == "--timeout" && has_value) timeout_s = std::atof(argv[++i]);
    else if(a == "--mem-limit-mib" && has_value) mem_limit_mib = std::atof(argv[++i]);
    else if(a == "--csv" && has_value) csv = argv[++i];
    else if(a == "--list") list_only = true;
    else return false;
    return true;
  }

  // The allowance of one child. Well below the available memory: the machines are shared, and a method that
  // runs out of it fails alone (std::bad_alloc, reported in the table) instead of waking the OOM killer.
  double memory_allowance_mib() const { return mem_limit_mib > 0 ? mem_limit_mib : 0.6 * mem_available_mib(); }

  std::string in_mesh_dir(const std::string& file) const { return (std::filesystem::path(mesh_dir) / file).string(); }
};

// The meshes to run: `builtin` and every .off/.obj/.ply file of --extra-dir (files named like a built-in mesh
// are skipped with a note), all of them or those named by --meshes in that order. Returns false (after a message
// on stderr) for an unknown name.
inline bool select_meshes(const std::vector<Mesh_spec>& builtin, const Common_options& o, std::vector<Mesh_spec>& specs)
{
  std::set<std::string> builtin_names;
  for(const auto& s : builtin) builtin_names.insert(s.name);
  std::vector<Mesh_spec> extras;
  if(!o.extra_dir.empty()) {
    std::error_code ec;
    std::vector<std::filesystem::path> files;
    for(const auto& entry : std::filesystem::directory_iterator(o.extra_dir, ec))
      if(entry.is_regular_file()) {
        std::string ext = entry.path().extension().string();
        std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
        if(ext == ".off" || ext == ".obj" || ext == ".ply") files.push_back(entry.path());
      }
    if(ec) std::cerr << "warning: cannot list --extra-dir " << o.extra_dir << ": " << ec.message() << "\n";
    std::sort(files.begin(), files.end());
    for(const auto& f : files) {
      const std::string stem = f.stem().string();
      if(builtin_names.count(stem)) {
        std::cout << "note: extra mesh " << f.string() << " has the name of a built-in mesh; it is skipped\n";
        continue;
      }
      extras.push_back({stem, f.string(), 0});
    }
  }
  std::set<std::string> known = builtin_names;
  for(const auto& s : extras) known.insert(s.name);
  specs.clear();
  if(o.selected.empty()) {
    specs = builtin;
    specs.insert(specs.end(), extras.begin(), extras.end());
    return true;
  }
  for(const auto& name : o.selected) {
    if(!known.count(name)) {
      std::cerr << "unknown mesh '" << name << "'\n";
      return false;
    }
    for(const auto& s : builtin) if(s.name == name) specs.push_back(s);
    for(const auto& s : extras) if(s.name == name) specs.push_back(s);
  }
  return true;
}

inline void print_mesh_list(const std::vector<Mesh_spec>& specs)
{
  for(const auto& s : specs)
    std::cout << s.name << "  " << s.file << (s.loop_steps ? "  + Loop x" + std::to_string(s.loop_steps) : "") << "\n";
}

// select_meshes(), then --list: returns -1 when the program goes on with `specs`, else its exit code (0 after
// printing the list, 2 after `usage()` for an unknown mesh name).
template <class Usage>
int select_or_list_meshes(const std::vector<Mesh_spec>& builtin, const Common_options& o, std::vector<Mesh_spec>& specs,
                          Usage usage)
{
  if(!select_meshes(builtin, o, specs)) {
    usage();
    return 2;
  }
  if(o.list_only) {
    print_mesh_list(specs);
    return 0;
  }
  return -1;
}

// Writes `table` as CSV to `csv` (parent folders created) and says so.
inline void write_table_csv(const mdcs_bench::Table& table, const std::string& csv)
{
  if(csv.empty()) return;
  const std::filesystem::path parent = std::filesystem::path(csv).parent_path();
  std::error_code ec;
  if(!parent.empty()) std::filesystem::create_directories(parent, ec);
  if(table.write_csv(csv)) std::cout << "\nCSV: " << csv << "\n";
  else std::cout << "\ncannot write CSV " << csv << "\n";
}

} // namespace geodesic_bench

#endif // MDCS_GEODESIC_BENCH_COMMON_H
