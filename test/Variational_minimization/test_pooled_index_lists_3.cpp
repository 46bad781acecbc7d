// Tests of the pooled list storage of Plane_arrangement_3 (internal::Pooled_index_lists_3): random assignments and
// appends, with packing and unpacking in between, against a vector of vectors.
#include <catch2/catch.hpp>

#include <CGAL/Variational_minimization/internal/pooled_index_lists_3.h>

#include <random>
#include <vector>

namespace VMI = CGAL::Variational_minimization::internal;

namespace {

void check_equal(const VMI::Pooled_index_lists_3& P, const std::vector<std::vector<std::uint32_t>>& R)
{
  REQUIRE(P.size() == R.size());
  std::size_t bad = 0;
  for(std::size_t i = 0; i < R.size(); ++i) {
    if(P.size(i) != R[i].size()) {
      ++bad;
      continue;
    }
    for(std::size_t k = 0; k < R[i].size(); ++k)
      if(P.at(i, k) != R[i][k] || P.begin(i)[k] != R[i][k]) ++bad;
    if(P.end(i) - P.begin(i) != std::ptrdiff_t(R[i].size())) ++bad;
  }
  CHECK(bad == 0);
}

} // namespace

TEST_CASE("Pooled_index_lists_3: random changes match a vector of vectors", "[variational][surface][arrangement]")
{
  for(std::uint32_t granularity : {1u, 2u, 4u}) {
    std::mt19937_64 rng(granularity);
    VMI::Pooled_index_lists_3 P(granularity);
    std::vector<std::vector<std::uint32_t>> R;
    std::vector<std::uint32_t> buffer;
    for(int step = 0; step < 60000; ++step) {
      const unsigned op = unsigned(rng() % 100);
      if(R.empty() || op < 10) {
        CHECK(P.add_list() == R.size());
        R.emplace_back();
      } else if(op < 55) { // assign: mostly short, sometimes long (past the 64-entry classes)
        const std::size_t i = std::size_t(rng() % R.size());
        const std::size_t n = rng() % 50 == 0 ? std::size_t(rng() % 600) : std::size_t(rng() % 20);
        buffer.resize(n);
        for(auto& v : buffer) v = std::uint32_t(rng());
        P.assign(i, buffer.data(), buffer.data() + n);
        R[i] = buffer;
      } else if(op < 99) {
        const std::size_t i = std::size_t(rng() % R.size());
        const std::uint32_t v = std::uint32_t(rng());
        P.push_back(i, v);
        R[i].push_back(v);
      } else {
        check_equal(P, R);
        P.compact();
        CHECK(P.memory_bytes() >= 4 * R.size());
      }
    }
    check_equal(P, R);
    P.compact();
    check_equal(P, R);
    P.compact(); // idempotent
    check_equal(P, R);
  }
}
