// A job file's bytes through what `epviz render` does with them first: the
// strict JSON reader, the job format and the checks of the simulation fields.
// Bad input must end in the error a user sees (exit 2),
// never in a crash; a job that is read must read back the same once written.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <nlohmann/json.hpp>
#include <string_view>

#include "io/bad_input.hpp"
#include "io/json_reader.hpp"
#include "job/resolve.hpp"
#include "job/schema.hpp"

namespace {

using namespace epviz;

void read_render_job(std::string_view text) {
  const auto json = io::parse_json_text(text, "fuzz.json");
  const job::JobDocument doc = job::read_job(json, "fuzz.json");

  // What write_job writes, read_job reads, and it describes the same job.
  const std::string written = job::write_job(doc).dump();
  const job::JobDocument again =
      job::read_job(io::parse_json_text(written, "written.json"), "written.json");
  if (job::write_job(again).dump() != written) std::abort();

  (void)job::resolve(doc.simulation);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    read_render_job({reinterpret_cast<const char*>(data), size});
  } catch (const io::BadInput&) {
  }
  return 0;
}
