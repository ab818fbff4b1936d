#include "section/section_csv.hpp"

#include <charconv>
#include <cmath>
#include <limits>

#include "io/atomic_file.hpp"
#include "io/bad_input.hpp"
#include "io/printable.hpp"
#include "physics/invariants.hpp"

namespace epviz::section {
namespace {

void put(std::string& out, double x) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, x);
  out.append(buf, r.ptr);
}

bool several_methods(const SectionJob& job) { return job.methods.size() > 1; }

// The comma-separated fields of one line.
std::vector<std::string_view> fields_of(std::string_view line) {
  std::vector<std::string_view> f;
  for (std::size_t at = 0;;) {
    const std::size_t comma = line.find(',', at);
    f.push_back(line.substr(at, comma == std::string_view::npos ? line.npos : comma - at));
    if (comma == std::string_view::npos) return f;
    at = comma + 1;
  }
}

template <class T>
bool parse(std::string_view text, T& value) {
  const auto r = std::from_chars(text.data(), text.data() + text.size(), value);
  return r.ec == std::errc{} && r.ptr == text.data() + text.size();
}

// The plotted Andoyer–Deprit variables, each once: the CSV's last columns.
std::vector<PlotCoord> andoyer_columns(const SectionJob& job) {
  std::vector<PlotCoord> v;
  for (const PlotCoord& c : job.coords)
    if (is_andoyer(c) && (v.empty() || !(v.front() == c))) v.push_back(c);
  return v;
}

}  // namespace

std::string crossings_csv_header(const SectionJob& job) {
  std::string h = several_methods(job) ? "method," : "";
  h += "orbit,crossing,t,omega1,omega2,omega3,gamma1,gamma2,gamma3,energy,area,gamma_norm_error,"
       "extra_integral";
  for (const PlotCoord& c : andoyer_columns(job)) {
    h += ',';
    h += name(c);
  }
  h += '\n';
  return h;
}

std::string crossings_csv(const SectionJob& job, const std::vector<OrbitResult>& orbits) {
  std::string out = crossings_csv_header(job);
  for (const auto& o : orbits) {
    if (o.failure) continue;
    const std::string label = several_methods(job) ? method_label(job.methods[o.method]) + "," : "";
    for (const auto& c : o.crossings) {
      const auto inv = physics::invariants(job.body, job.case_id, c.omega, c.gamma);
      out += label;
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
      for (const PlotCoord& a : andoyer_columns(job)) {  // empty where undefined
        out += ',';
        if (const auto v = value_of(a, job.body, c.omega, c.gamma)) put(out, *v);
      }
      out += '\n';
    }
  }
  return out;
}

std::vector<std::string> crossing_columns(const SectionJob& job) {
  std::vector<std::string> names;
  const std::string header = crossings_csv_header(job);
  for (auto f : fields_of(std::string_view(header).substr(0, header.size() - 1)))
    names.emplace_back(f);
  return names;
}

void for_each_crossing_row(const SectionJob& job, const std::vector<OrbitResult>& orbits,
                           const std::function<void(std::span<const double>)>& row) {
  std::vector<double> values;
  for (const auto& o : orbits) {
    if (o.failure) continue;
    for (const auto& c : o.crossings) {
      const auto inv = physics::invariants(job.body, job.case_id, c.omega, c.gamma);
      values.clear();
      if (several_methods(job)) values.push_back(double(o.method));
      for (double x : {double(o.orbit), double(c.number), c.t, c.omega.x(), c.omega.y(),
                       c.omega.z(), c.gamma.x(), c.gamma.y(), c.gamma.z(), inv.energy, inv.area,
                       std::sqrt(inv.gamma_norm2) - 1.0})
        values.push_back(x);
      values.push_back(inv.extra ? *inv.extra : std::numeric_limits<double>::quiet_NaN());
      for (const PlotCoord& a : andoyer_columns(job))
        values.push_back(value_of(a, job.body, c.omega, c.gamma)
                             .value_or(std::numeric_limits<double>::quiet_NaN()));
      row(values);
    }
  }
}

void write_crossings_csv(const SectionJob& job, const std::vector<OrbitResult>& orbits) {
  io::write_file_atomically(job.csv, crossings_csv(job, orbits));
}

std::vector<OrbitResult> crossings_from_csv(const SectionJob& job, std::string_view text,
                                            const std::string& file) {
  const std::string header = crossings_csv_header(job);
  if (!text.starts_with(header))
    throw io::BadInput(file + ": line 1: expected the header " +
                       header.substr(0, header.size() - 1));
  const std::vector<std::string> columns = crossing_columns(job);
  std::vector<OrbitResult> results;
  std::size_t at = header.size();
  const std::size_t first_field = several_methods(job) ? 1 : 0;
  for (long line_number = 2; at < text.size(); ++line_number) {
    const std::size_t end = text.find('\n', at);
    const auto fail = [&](const std::string& what) {
      throw io::BadInput(file + ": line " + std::to_string(line_number) + ": " + what);
    };
    if (end == std::string_view::npos) fail("cut short (no newline)");
    const auto f = fields_of(text.substr(at, end - at));
    at = end + 1;
    if (f.size() != columns.size()) fail("expected as many fields as the header");
    std::size_t method = 0;
    if (several_methods(job)) {
      while (method < job.methods.size() && method_label(job.methods[method]) != f[0]) ++method;
      if (method == job.methods.size())
        fail(std::string("method '") + io::printable(f[0]) + "' is not one of the section's");
    }
    // Every value a number the merge can draw and join: "nan" or "inf" parse
    // as doubles but are no crossing's (extra_integral is empty where the
    // case has none).
    // extra_integral and the Andoyer–Deprit columns after it may be empty.
    const std::size_t first_optional = first_field + 12;
    for (std::size_t k = first_field + 2; k < f.size(); ++k) {
      double x = 0.0;
      if (k >= first_optional && f[k].empty()) continue;
      if (!parse(f[k], x) || !std::isfinite(x))
        fail("column '" + columns[k] + "': expected a finite number, got '" + io::printable(f[k]) +
             "'");
    }
    sim::Crossing c;
    int orbit = 0;
    double v[7];
    bool ok = parse(f[first_field], orbit) && parse(f[first_field + 1], c.number) && orbit >= 1 &&
              c.number >= 1;
    for (int k = 0; k < 7; ++k) ok = ok && parse(f[first_field + 2 + std::size_t(k)], v[k]);
    if (!ok) fail("expected an orbit and crossing number (from 1) and numbers t, omega, gamma");
    c.t = v[0];
    c.omega = {v[1], v[2], v[3]};
    c.gamma = {v[4], v[5], v[6]};
    const bool same_run =
        !results.empty() && results.back().orbit == orbit && results.back().method == method;
    if (!same_run) {
      const bool later = results.empty() || method > results.back().method ||
                         (method == results.back().method && orbit > results.back().orbit);
      if (!later || c.number != 1) fail("runs out of order or a crossing missing");
      results.push_back({orbit, method, {}, {}, {}});
    } else if (c.number != results.back().crossings.back().number + 1) {
      fail("crossings of an orbit out of order");
    }
    results.back().crossings.push_back(c);
  }
  return results;
}

}  // namespace epviz::section
