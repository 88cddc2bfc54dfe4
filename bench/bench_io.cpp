// Reader and writer throughput on generated point sets (the paper's inputs are 10^4..10^6
// points): for each size and format, the median of several runs of write_mesh_to_string
// and read_mesh_from_memory, in memory so that the disk does not enter the figures.
// Prints size, format, bytes, write and read seconds (median), read MB/s and a checksum.
// Usage: bench_io [runs=5] [max_size=1000000]

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

#include "rstruct/core/stopwatch.hpp"
#include "rstruct/io/mesh_io.hpp"

using namespace rstruct;

namespace {

TriangleMesh random_points(std::size_t n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> normal;
  TriangleMesh m;
  m.vertices.reserve(n);
  std::vector<double> radius(n);
  for (std::size_t i = 0; i < n; ++i) {
    Point3 p{normal(rng), normal(rng), normal(rng)};
    m.vertices.push_back(p / norm(p));  // on the unit sphere: full-precision doubles
    radius[i] = 0.01 * (1 + normal(rng) * normal(rng));
  }
  m.vertex_properties.emplace_back("radius", std::move(radius));
  for (std::size_t i = 0; i + 2 < n; i += 3) {
    m.faces.push_back({static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(i + 1),
                       static_cast<std::uint32_t>(i + 2)});
  }
  return m;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

double checksum(const TriangleMesh& m) {
  double s = 0;
  for (const Point3& p : m.vertices) s += p.x + 2 * p.y + 3 * p.z;
  return s + static_cast<double>(m.faces.size());
}

struct Case {
  const char* name;
  io::Format format;
  bool ascii;
};

}  // namespace

int main(int argc, char** argv) {
  const int runs = argc > 1 ? std::max(1, std::atoi(argv[1])) : 5;
  const std::size_t max_size = argc > 2 ? std::strtoull(argv[2], nullptr, 10) : 1000000;
  const Case cases[] = {{"ply-binary", io::Format::ply, false},
                        {"ply-ascii", io::Format::ply, true},
                        {"off", io::Format::off, false},
                        {"obj", io::Format::obj, false},
                        {"xyz", io::Format::xyz, false}};
  std::printf("%9s %-10s %12s %10s %10s %9s %s\n", "points", "format", "bytes", "write_s",
              "read_s", "read_MB/s", "checksum");
  for (std::size_t n : {std::size_t{10000}, std::size_t{85237}, std::size_t{1000000}}) {
    if (n > max_size) break;
    const TriangleMesh m = random_points(n, 42);
    for (const Case& c : cases) {
      std::vector<double> write_s, read_s;
      std::string bytes;
      double sum = 0;
      for (int r = 0; r < runs; ++r) {
        Stopwatch w;
        bytes = io::write_mesh_to_string(m, io::WriteOptions{c.format, c.ascii});
        write_s.push_back(w.seconds());
        Stopwatch rd;
        const TriangleMesh back = io::read_mesh_from_memory(bytes, c.format);
        read_s.push_back(rd.seconds());
        sum = checksum(back);
      }
      const double read = median(read_s);
      std::printf("%9zu %-10s %12zu %10.4f %10.4f %9.1f %.17g\n", n, c.name, bytes.size(),
                  median(write_s), read, static_cast<double>(bytes.size()) / 1e6 / read, sum);
    }
  }
  return 0;
}
