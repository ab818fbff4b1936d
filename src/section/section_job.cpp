#include "section/section_job.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "io/bad_input.hpp"
#include "io/json_reader.hpp"
#include "io/json_text.hpp"
#include "io/output_paths.hpp"
#include "io/printable.hpp"
#include "physics/admissible.hpp"
#include "shard/checksum.hpp"

namespace epviz::section {
namespace {

constexpr double kMaxCrossings = 1e7;
constexpr double kMaxFixedSteps = 1e8;

std::vector<std::string> names_of_cases() {
  std::vector<std::string> v;
  for (const auto& p : physics::case_presets()) v.push_back(p.name);
  return v;
}

template <class T, class List, class Name>
std::vector<std::string> names_of(const List& list, Name name_fn) {
  std::vector<std::string> v;
  for (const T& x : list) v.emplace_back(name_fn(x));
  return v;
}

physics::Vector3d vec(const std::array<double, 3>& a) { return {a[0], a[1], a[2]}; }

std::vector<std::string> function_names() {
  return names_of<sim::StateComponent>(sim::all_state_components(),
                                       [](sim::StateComponent c) { return sim::name(c); });
}

std::string join(const std::vector<std::string>& names) {
  std::string s;
  for (const auto& n : names) {
    if (!s.empty()) s += ", ";
    s += n;
  }
  return s;
}

std::vector<physics::InitialState> read_states(const io::ObjectReader& root,
                                               const std::string& file,
                                               const nlohmann::json& array) {
  if (!array.is_array() || array.empty() || array.size() > 100000)
    root.fail("states", "must be an array of 1 to 100000 objects {\"omega\", \"gamma\"}");
  std::vector<physics::InitialState> states;
  for (std::size_t i = 0; i < array.size(); ++i) {
    std::string key = "states[";
    key += std::to_string(i);
    key += "]";
    if (!array[i].is_object()) root.fail(key, "must be an object {\"omega\", \"gamma\"}");
    io::ObjectReader r(array[i], file, key);
    physics::InitialState s;
    const auto omega = r.vec3("omega");
    const auto gamma = r.vec3("gamma");
    if (!omega || !gamma) root.fail(key, "needs both \"omega\" and \"gamma\" (3 numbers each)");
    r.finish();
    s.omega = vec(*omega);
    s.gamma = vec(*gamma);
    if (!(s.omega.cwiseAbs().maxCoeff() <= 1e6))
      root.fail(key, "omega's components must be at most 1e6 in magnitude");
    if (std::abs(s.gamma.norm() - 1.0) > 1e-9)
      root.fail(key, "gamma must be a unit vector to 1e-9");
    states.push_back(s);
  }
  return states;
}

// One method and its setting from `r` ("method", "tol", "step"), the
// missing ones as in `m`.
SectionMethod read_method(io::ObjectReader& r, SectionMethod m, double t_end,
                          bool method_required) {
  const auto methods =
      names_of<sim::Method>(sim::all_methods(), [](sim::Method x) { return sim::name(x); });
  const auto name = r.choice("method", methods);
  if (name) m.method = *sim::method_from_name(*name);
  if (!name && method_required) r.fail("method", "is required: one of " + join(methods));
  if (auto tol = r.number_in("tol", 1e-15, 1e-3, "1e-15 to 1e-3")) m.tol = *tol;
  if (auto h = r.number_in("step", 1e-6, 1.0, "1e-6 to 1")) m.step = *h;
  if (!sim::is_adaptive(m.method) && t_end / m.step > kMaxFixedSteps)
    r.fail("step", "t_end / step must be at most 1e8 steps for a fixed-step method");
  return m;
}

// "method", "tol", "step" at the top, or a list "methods" of such objects
// (the top's "tol" and "step" their defaults): the figure's panels.
void read_methods(io::ObjectReader& r, SectionJob& job) {
  const SectionMethod top = read_method(r, SectionMethod{}, job.t_end, false);
  job.methods = {top};
  const auto* list = r.raw("methods");
  if (!list) return;
  if (r.raw("method")) r.fail("methods", "give either \"method\" or \"methods\", not both");
  if (!list->is_array() || list->empty() || list->size() > kMaxSectionMethods)
    r.fail("methods", "must be an array of 1 to 8 objects {\"method\", \"tol\" or \"step\"}");
  job.methods.clear();
  std::vector<std::string> labels;
  for (std::size_t i = 0; i < list->size(); ++i) {
    std::string key = "methods[";
    key += std::to_string(i);
    key += "]";
    if (!(*list)[i].is_object()) r.fail(key, "must be an object {\"method\", \"tol\" or \"step\"}");
    io::ObjectReader one((*list)[i], job.file, key);
    job.methods.push_back(read_method(one, top, job.t_end, true));
    one.finish();
    const std::string label = method_label(job.methods.back());
    if (std::find(labels.begin(), labels.end(), label) != labels.end())
      r.fail(key, label + " is listed twice");
    labels.push_back(label);
  }
}

std::string short_number(double x) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, x, std::chars_format::general, 6);
  return std::string(buf, r.ptr);
}

}  // namespace

std::string method_label(const SectionMethod& m) {
  std::string s(sim::name(m.method));
  s += sim::is_adaptive(m.method) ? " tol " : " step ";
  s += short_number(sim::is_adaptive(m.method) ? m.tol : m.step);
  return s;
}

// Where the surface is gamma3 = c the plot shows gamma1 against omega3 (the
// angle of gamma about the third axis, and the spin about it); for another
// surface, the first two components other than its own.
std::array<sim::StateComponent, 2> default_coords(sim::StateComponent surface) {
  if (surface == sim::StateComponent::gamma3)
    return {sim::StateComponent::gamma1, sim::StateComponent::omega3};
  std::array<sim::StateComponent, 2> c{};
  std::size_t n = 0;
  for (auto f : sim::all_state_components())
    if (f != surface && n < 2) c[n++] = f;
  return c;
}

std::vector<std::string> state_function_names() { return function_names(); }

std::string surface_value_range() { return "-1e6 to 1e6"; }  // kSurfaceValueLimit

void read_surface_function(io::ObjectReader& r, sim::SectionSurface& s) {
  if (auto f = r.choice("function", function_names()))
    s.function = *sim::state_component_from_name(*f);
}

void read_surface_value(io::ObjectReader& r, sim::SectionSurface& s) {
  if (auto v = r.number_in("value", -kSurfaceValueLimit, kSurfaceValueLimit, surface_value_range()))
    s.value = *v;
}

void read_surface_direction(io::ObjectReader& r, sim::SectionSurface& s) {
  if (auto d = r.choice("direction", {"upward", "downward", "both"}))
    s.direction = *sim::crossing_direction_from_name(*d);
}

void read_surface(io::ObjectReader& r, sim::SectionSurface& s) {
  read_surface_function(r, s);
  read_surface_value(r, s);
  read_surface_direction(r, s);
}

std::array<sim::StateComponent, 2> read_coords(io::ObjectReader& r, sim::StateComponent surface) {
  std::array<sim::StateComponent, 2> coords = default_coords(surface);
  if (const auto* given = r.raw("coords")) {
    const std::string allowed = "two of " + join(function_names());
    if (!given->is_array() || given->size() != 2) r.fail("coords", "must be " + allowed);
    for (std::size_t i = 0; i < 2; ++i) {
      const auto c = (*given)[i].is_string()
                         ? sim::state_component_from_name((*given)[i].get<std::string>())
                         : std::nullopt;
      if (!c) r.fail("coords", "must be " + allowed + ", got " + io::describe(*given));
      coords[i] = *c;
    }
  }
  return coords;
}

void read_section_function(io::ObjectReader& r, sim::SectionSurface& s) {
  std::vector<std::string> names = function_names();
  for (auto a : {physics::AndoyerAngle::l, physics::AndoyerAngle::g})
    names.emplace_back(sim::name(a));
  const auto f = r.choice("function", names);
  if (!f) return;
  s.angle = sim::andoyer_angle_from_name(*f);
  if (!s.angle) s.function = *sim::state_component_from_name(*f);
}

PlotCoords default_section_coords(const sim::SectionSurface& s) {
  if (!s.angle) {
    const auto c = default_coords(s.function);
    return {c[0], c[1]};
  }
  if (*s.angle == physics::AndoyerAngle::g) return {AndoyerCoord::l, AndoyerCoord::L_over_G};
  return {AndoyerCoord::g, AndoyerCoord::G};
}

PlotCoords read_section_coords(io::ObjectReader& r, const sim::SectionSurface& s) {
  PlotCoords coords = default_section_coords(s);
  if (const auto* given = r.raw("coords")) {
    std::vector<std::string> names;
    for (const PlotCoord& c : all_plot_coords()) names.emplace_back(name(c));
    const std::string allowed = "two of " + join(names);
    if (!given->is_array() || given->size() != 2) r.fail("coords", "must be " + allowed);
    for (std::size_t i = 0; i < 2; ++i) {
      const auto c = (*given)[i].is_string() ? plot_coord_from_name((*given)[i].get<std::string>())
                                             : std::nullopt;
      if (!c) r.fail("coords", "must be " + allowed + ", got " + io::describe(*given));
      coords[i] = *c;
    }
  }
  return coords;
}

// "sheet": "COMPONENT > 0" or "COMPONENT < 0", or "sheets": "COMPONENT": a
// state component that is neither the surface's nor plotted.
std::optional<SheetChoice> read_sheet(io::ObjectReader& r, const sim::SectionSurface& surface,
                                      const PlotCoords& coords, bool both_allowed) {
  const auto one = r.string("sheet");
  const auto both = both_allowed ? r.string("sheets") : std::nullopt;
  if (one && both)
    r.fail("sheet", "give \"sheet\" (one sheet) or \"sheets\" (both apart), not both");
  if (!one && !both) return std::nullopt;
  const char* key = one ? "sheet" : "sheets";
  std::string free;  // the components a sheet may be told apart by
  for (auto c : sim::all_state_components())
    if ((surface.angle || c != surface.function) && c != coords[0] && c != coords[1])
      free += (free.empty() ? "" : ", ") + std::string(sim::name(c));
  const std::string allowed = one ? "\"C > 0\" or \"C < 0\", C one of " + free : "one of " + free;
  std::string text = one ? *one : *both;
  SheetChoice sheet;
  if (one) {
    const auto space = text.find(' ');
    const std::string side = space == std::string::npos ? "" : text.substr(space);
    if (side != " > 0" && side != " < 0")
      r.fail(key, "must be " + allowed + ", got " + io::quoted(text));
    sheet.show = side == " > 0" ? SheetChoice::Show::positive : SheetChoice::Show::negative;
    text = text.substr(0, space);
  }
  const auto c = sim::state_component_from_name(text);
  if (!c || (!surface.angle && *c == surface.function) || *c == coords[0] || *c == coords[1])
    r.fail(key, "must be " + allowed + ", got " + io::quoted(one ? *one : *both));
  sheet.component = *c;
  return sheet;
}

namespace {

// "figure_width": "85mm", "font_size": 8, "dpi": 300, checked as the
// command line's options are (io/print_size.hpp) but named by their keys.
void read_print_size(io::ObjectReader& r, SectionJob& job) {
  // The numbers as text (15 digits, as typed), for the options' parsers.
  const auto text = [](double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.15g", v);
    return std::string(buf);
  };
  if (auto width = r.string("figure_width")) job.print.width = *width;
  if (auto font = r.number("font_size")) job.print.font = text(*font);
  if (auto dpi = r.number("dpi")) job.print.dpi = text(*dpi);
  if (job.print.width.empty())
    for (const char* key : {"font_size", "dpi"})
      if (r.has(key))
        r.fail(key, "applies to a figure of a printed size; give \"figure_width\" too");
  const io::PrintSizeText names = print_key_names(job);
  (void)io::parse_print_size(job.print, names.width, names.font, names.dpi);
}

}  // namespace

// Named as ObjectReader names a key of the file's top level.
io::PrintSizeText print_key_names(const SectionJob& job) {
  static const nlohmann::json top = nlohmann::json::object();
  const io::ObjectReader r(top, job.file);
  return {r.where("figure_width"), r.where("font_size"), r.where("dpi")};
}

SectionRun section_run_of(long run, std::size_t starts) {
  return {std::size_t(run) / starts, std::size_t(run) % starts};
}

SectionJob read_section_job(const std::filesystem::path& file) {
  return read_section_object(io::read_json_file(file), file.string());
}

SectionJob read_section_object(const nlohmann::json& doc, const std::string& name, bool needs_csv) {
  SectionJob job;
  job.file = name;
  job.hash = shard::checksum_of(io::json_text(doc));  // nlohmann::json keeps keys sorted
  io::ObjectReader r(doc, job.file);
  const auto case_name = r.choice("case", names_of_cases());
  if (!case_name) r.fail("case", "is required: one of the named cases");
  job.case_id = *physics::case_from_name(*case_name);
  job.body = physics::preset(job.case_id).body;

  if (auto level = r.object("level")) {
    const auto energy = level->number_in("energy", -1e6, 1e6, "-1e6 to 1e6");
    const auto area = level->number_in("area", -1e6, 1e6, "-1e6 to 1e6");
    if (!energy || !area) r.fail("level", "needs \"energy\" (C1) and \"area\" (C0)");
    level->finish();
    job.level = physics::Level{*energy, *area};
  }
  const auto orbits = r.integer("orbits", 1, 100000);
  if (const auto* states = r.raw("states")) job.states = read_states(r, job.file, *states);
  if (job.level.has_value() == !job.states.empty())
    r.fail("level", "give either \"level\" with \"orbits\" or \"states\", not both or neither");
  if (job.level && !orbits) r.fail("orbits", "is required with \"level\": 1 to 100000");
  if (!job.level && orbits) r.fail("orbits", "goes with \"level\"; \"states\" count themselves");
  job.orbits = orbits ? int(*orbits) : int(job.states.size());

  if (auto k = r.integer("crossings", 1, 1000000)) job.crossings = int(*k);
  if (auto t = r.number_in("t_end", 1e-6, 1e9, "1e-6 to 1e9")) job.t_end = *t;
  if (auto s = r.object("section")) {
    read_section_function(*s, job.surface);
    read_surface_value(*s, job.surface);
    read_surface_direction(*s, job.surface);
    s->finish();
  }
  read_methods(r, job);
  // The crossings are kept until the CSV is written: about 300 bytes each.
  if (double(job.orbits) * job.crossings * double(job.methods.size()) > kMaxCrossings) {
    std::string got = "orbits x crossings (x methods) must be at most 1e7, got ";
    got += std::to_string(job.orbits);
    got += " x ";
    got += std::to_string(job.crossings);
    if (job.methods.size() > 1) {
      got += " x ";
      got += std::to_string(job.methods.size());
    }
    r.fail("crossings", got);
  }
  if (auto d = r.number_in("max_drift", 1e-14, 1.0, "1e-14 to 1")) job.max_drift = *d;
  job.coords = read_section_coords(r, job.surface);
  job.sheet = read_sheet(r, job.surface, job.coords);
  for (auto [key, path] : {std::pair{"png", &job.png}, {"svg", &job.svg}, {"pdf", &job.pdf}})
    if (auto given = r.string(key)) *path = *given;
  read_print_size(r, job);
  const auto csv = r.string("csv");
  if (needs_csv && (!csv || csv->empty())) r.fail("csv", "is required: the crossings' CSV file");
  if (csv) job.csv = *csv;
  r.finish();
  return job;
}

void check_outputs(const SectionJob& job, const std::string& csv_from, const io::NamedPaths& more) {
  io::NamedPaths outputs;
  for (const auto& [key, path] :
       {std::pair{"csv", job.csv}, {"png", job.png}, {"svg", job.svg}, {"pdf", job.pdf}}) {
    std::string where = job.file;
    where += ": key '";
    where += key;
    where += "'";
    if (key[0] == 'c' && !csv_from.empty()) where = csv_from;
    io::check_output_file(where, path);
    outputs.emplace_back(where, path);
  }
  outputs.insert(outputs.end(), more.begin(), more.end());
  // The pictures are written after the CSV: one naming its file would replace
  // it; and an output naming the section file would replace the run's own input.
  io::require_separate_files({{"the section file", job.file}}, outputs);
}

std::vector<physics::InitialState> section_starts(const SectionJob& job) {
  std::vector<physics::InitialState> starts = job.states;
  std::string key = "states";
  if (job.level) {
    key = "level";
    starts = physics::level_states(job.body, *job.level, job.orbits).states;
    // Close above the least energy only a small cap of directions carries
    // states, which the grid over the sphere misses.
    if (starts.empty())
      starts = physics::level_states_about_minimum(job.body, *job.level, job.orbits).states;
    if (starts.empty()) {
      const double least = physics::minimum_energy(job.body, job.level->area).energy;
      char what[160];
      std::snprintf(what, sizeof what,
                    "no state of this body lies on it; the least energy at this area is %.17g "
                    "(the energy must be at least that)",
                    least);
      throw io::BadInput(job.file + ": key 'level': " + what);
    }
  }
  for (const auto& s : starts)
    if (auto broken = physics::broken_condition(job.case_id, job.body, s))
      throw io::BadInput(job.file + ": key '" + key + "': " + *broken);
  return starts;
}

}  // namespace epviz::section
