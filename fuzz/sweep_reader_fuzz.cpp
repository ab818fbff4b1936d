// A sweep file's bytes through what `epviz sweep` does with them before any
// run: the strict JSON reader, the sweep format (axes, ranges, atlas), every
// point's fields read by the job format's reader, checked against physics,
// and its energy level set. Bad input must end in the error a user sees
// (exit 2), never in a crash.
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string_view>

#include "io/bad_input.hpp"
#include "io/json_reader.hpp"
#include "job/resolve.hpp"
#include "sweep/sweep_point.hpp"
#include "sweep/sweep_spec.hpp"

namespace {

using namespace epviz;

// A fuzzer's sweep may have millions of points; the first ones exercise the
// same code as the rest.
constexpr long kPointsTried = 256;

void read_sweep(std::string_view text) {
  const auto spec = sweep::read_sweep(io::parse_json_text(text, "fuzz.json"), "fuzz.json");
  const long n = spec.point_count();
  if (n < 1 || n > sweep::max_points) std::abort();
  sweep::PointReader read_point(spec);
  for (long i = 0; i < n && i < kPointsTried; ++i) {
    const auto c = spec.coordinates(i);
    for (std::size_t k = 0; k < c.size(); ++k)
      if (c[k] >= spec.axes[k].values.size()) std::abort();
    const auto p = read_point(i);
    (void)sweep::resolve_point(p, [](const job::SimulationFields& f) { return job::resolve(f); });
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    read_sweep({reinterpret_cast<const char*>(data), size});
  } catch (const io::BadInput&) {
  } catch (const std::invalid_argument&) {  // an energy level no omega reaches
  }
  return 0;
}
