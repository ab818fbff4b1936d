#include "section/section_csv.hpp"

#include <charconv>
#include <cmath>

#include "io/atomic_file.hpp"
#include "physics/invariants.hpp"

namespace epviz::section {
namespace {

void put(std::string& out, double x) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, x);
  out.append(buf, r.ptr);
}

}  // namespace

std::string crossings_csv(const SectionJob& job, const std::vector<OrbitResult>& orbits) {
  std::string out =
      "orbit,crossing,t,omega1,omega2,omega3,gamma1,gamma2,gamma3,energy,area,gamma_norm_error,"
      "extra_integral\n";
  for (const auto& o : orbits) {
    if (o.failure) continue;
    for (const auto& c : o.crossings) {
      const auto inv = physics::invariants(job.body, job.case_id, c.omega, c.gamma);
      out += std::to_string(o.orbit);
      out += ',';
      out += std::to_string(c.number);
      for (double x : {c.t, c.omega.x(), c.omega.y(), c.omega.z(), c.gamma.x(), c.gamma.y(),
                       c.gamma.z(), inv.energy, inv.area, std::sqrt(inv.gamma_norm2) - 1.0}) {
        out += ',';
        put(out, x);
      }
      out += ',';
      if (inv.extra) put(out, *inv.extra);
      out += '\n';
    }
  }
  return out;
}

void write_crossings_csv(const SectionJob& job, const std::vector<OrbitResult>& orbits) {
  io::write_file_atomically(job.csv, crossings_csv(job, orbits));
}

}  // namespace epviz::section
