#include "job/schema.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <functional>
#include <variant>

#include "io/bad_input.hpp"
#include "io/printable.hpp"
#include "job/schema_entries.hpp"
#include "scene/layers.hpp"
#include "scene/theme.hpp"
#include "section/section_job.hpp"
#include "sim/section.hpp"

namespace epviz::job {

using namespace entries;

namespace {

using Vec3 = std::array<double, 3>;

// ---- the "simulation" object: SimulationFields -----------------------------

using Sim = Entry<SimulationFields>;

void read_value(io::ObjectReader& r, const FieldInfo& info, Given<std::string>& g) {
  if (auto v = r.string(info.key)) g.set(*v, r.where(info.key));
}
// Each of `numbers` within the field's range, or an error naming the range.
template <class Numbers>
void require_in_range(io::ObjectReader& r, const FieldInfo& info, const Numbers& numbers) {
  for (double x : numbers)
    if (!info.in_range(x))
      r.fail(info.key, "expected " + info.range_text() + ", got " + io::describe(*r.raw(info.key)));
}
void read_value(io::ObjectReader& r, const FieldInfo& info, Given<Vec3>& g) {
  if (auto v = r.vec3(info.key)) {
    require_in_range(r, info, *v);
    g.set(*v, r.where(info.key));
  }
}
void read_value(io::ObjectReader& r, const FieldInfo& info, Given<double>& g) {
  if (auto v = r.number(info.key)) {
    require_in_range(r, info, std::array<double, 1>{*v});
    g.set(*v, r.where(info.key));
  }
}
void read_value(io::ObjectReader& r, const FieldInfo& info, Given<long>& g) {
  if (auto v = r.integer(info.key, long(info.min), long(info.max))) g.set(*v, r.where(info.key));
}
void read_value(io::ObjectReader& r, const FieldInfo& info, Given<bool>& g) {
  if (auto v = r.boolean(info.key)) g.set(*v, r.where(info.key));
}

ValueType value_type(FieldType t) {
  switch (t) {
    case FieldType::text: return ValueType::text;
    case FieldType::vec3: return ValueType::vec3;
    case FieldType::number: return ValueType::number;
    case FieldType::integer: return ValueType::integer;
    case FieldType::flag: return ValueType::boolean;
  }
  return ValueType::text;
}

// One key of the "simulation" object, from its field (job/fields.hpp).
Sim sim_entry(const FieldInfo& info) {
  std::string allowed = info.type == FieldType::text   ? info.choices
                        : info.type == FieldType::flag ? "true, false"
                                                       : info.range_text();
  // A render job's tolerance may also follow its resolution.
  if (info.key == "tol") allowed += ", or \"auto\"";
  return {{info.key, value_type(info.type), info.key == "tol" ? "auto" : info.default_value,
           allowed, info.help},
          [&info](io::ObjectReader& r, SimulationFields& f) {
            std::visit([&](auto m) { read_value(r, info, f.*m); }, info.member);
          },
          [&info](const SimulationFields& f, Json& j) {
            std::visit(
                [&](auto m) {
                  if (f.*m) j[info.key] = *(f.*m);
                },
                info.member);
          }};
}

// "tol": "auto" is read by read_simulation_fields itself.
const std::vector<Sim>& simulation_entries() {
  static const std::vector<Sim> entries = [] {
    std::vector<Sim> e;
    for (const auto& info : simulation_field_table()) e.push_back(sim_entry(info));
    return e;
  }();
  return entries;
}

// ---- a whole render job: JobDocument ---------------------------------------

using Job = Entry<JobDocument>;

// "#rrggbb" or "#rrggbbaa".
scene::Rgba parse_colour(const io::ObjectReader& r, const std::string& key,
                         const std::string& text) {
  const std::string expected =
      "expected a colour \"#rrggbb\" or \"#rrggbbaa\", got \"" + io::printable(text) + "\"";
  if (text.empty() || text[0] != '#' || (text.size() != 7 && text.size() != 9))
    r.fail(key, expected);
  auto hex = [&](std::size_t i) {
    if (!std::isxdigit(unsigned(text[i])) || !std::isxdigit(unsigned(text[i + 1])))
      r.fail(key, expected);
    return float(std::stoi(text.substr(i, 2), nullptr, 16)) / 255.0f;
  };
  return {hex(1), hex(3), hex(5), text.size() == 9 ? hex(7) : 1.0f};
}

Job colour(const char* key, scene::Rgba scene::Colours::*m, std::string help) {
  return {{key, ValueType::colour, hex_colour(scene::dark_theme().colours.*m),
           "\"#rrggbb\" or \"#rrggbbaa\"", std::move(help) + " (default: the theme's)"},
          [=](io::ObjectReader& r, JobDocument& d) {
            if (auto s = r.string(key)) d.scene.colours.*m = parse_colour(r, key, *s);
          },
          [=](const JobDocument& d, Json& j) { j[key] = hex_colour(d.scene.colours.*m); }};
}

Job layer(const scene::LayerInfo& l) {
  return {{l.key, ValueType::boolean, l.default_on ? "true" : "false", "true, false", l.help},
          [&l](io::ObjectReader& r, JobDocument& d) {
            if (auto v = r.boolean(l.key)) d.scene.layers.*l.member = *v;
          },
          [&l](const JobDocument& d, Json& j) { j[l.key] = d.scene.layers.*l.member; }};
}

std::vector<Job> layer_entries() {
  std::vector<Job> entries;
  for (const auto& l : scene::layer_table()) entries.push_back(layer(l));
  return entries;
}

std::string fmt(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

// "runs": [{"label": ..., <simulation keys>}, ...]. Every run shares the
// job's frame times, so t_end and samples stay the job's.
void read_runs(io::ObjectReader& r, JobDocument& d) {
  const auto* list = r.raw("runs");
  if (!list) return;
  const std::string allowed =
      "an array of 1 to " + std::to_string(max_runs) + " objects (\"label\" and simulation keys)";
  if (!list->is_array() || list->empty() || list->size() > std::size_t(max_runs))
    r.fail("runs", "expected " + allowed + ", got " + io::describe(*list));
  // The reader names its file only in messages: take it from one.
  const std::string here = r.where("runs");
  const std::string file = here.substr(0, here.rfind(": key '"));
  for (std::size_t i = 0; i < list->size(); ++i) {
    const auto& item = (*list)[i];
    const std::string key = "runs[" + std::to_string(i) + "]";
    if (!item.is_object()) r.fail("runs", "item " + std::to_string(i) + ": expected an object");
    io::ObjectReader o(item, file, key);
    RunFields run;
    if (auto v = o.string("label")) run.label = *v;
    for (const char* shared : {"t_end", "samples"})
      if (o.has(shared))
        o.fail(shared, "every run of a job shares its frame times: give " + std::string(shared) +
                           " in \"simulation\" only");
    run.simulation = read_simulation_fields(o, &run.auto_tolerance);
    o.finish();
    d.runs.push_back(std::move(run));
  }
}

// A key of the "section" object: read by the section file's own reader
// (section/section_job.hpp) into the job's panel, which the object's being
// given creates (an empty object asks for every default).
using SectionRead = void (*)(io::ObjectReader&, scene::SectionPanelSettings&);
using SectionWrite = void (*)(const scene::SectionPanelSettings&, Json&);
Entry<JobDocument> section_key(const char* key, ValueType type, std::string default_value,
                               std::string allowed, const char* help, SectionRead read,
                               SectionWrite write) {
  return {{key, type, std::move(default_value), std::move(allowed), help},
          [read](io::ObjectReader& r, JobDocument& d) {
            read(r, d.scene.section ? *d.scene.section : d.scene.section.emplace());
          },
          [write](const JobDocument& d, Json& j) {
            if (d.scene.section) write(*d.scene.section, j);
          }};
}

// "orbits" of a job's "section": starts on the section's surface, in full.
void read_section_orbits(io::ObjectReader& r, scene::SectionPanelSettings& p) {
  const auto* list = r.raw("orbits");
  if (!list) return;
  const std::string allowed = "an array of up to " + std::to_string(scene::kMaxSectionOrbits) +
                              " objects with \"omega\" and \"gamma\"";
  if (!list->is_array() || list->size() > std::size_t(scene::kMaxSectionOrbits))
    r.fail("orbits", "expected " + allowed + ", got " + io::describe(*list));
  const std::string here = r.where("orbits");
  const std::string file = here.substr(0, here.rfind(": key '"));
  p.orbits.clear();
  for (std::size_t i = 0; i < list->size(); ++i) {
    const std::string item = "item " + std::to_string(i) + ": ";
    if (!(*list)[i].is_object()) r.fail("orbits", item + "expected " + allowed);
    io::ObjectReader o((*list)[i], file, "section.orbits[" + std::to_string(i) + "]");
    physics::InitialState s;
    const auto omega = o.vec3("omega");
    const auto gamma = o.vec3("gamma");
    if (!omega || !gamma) r.fail("orbits", item + "needs both \"omega\" and \"gamma\"");
    o.finish();
    s.omega = {(*omega)[0], (*omega)[1], (*omega)[2]};
    s.gamma = {(*gamma)[0], (*gamma)[1], (*gamma)[2]};
    try {
      s = physics::validate_initial_state(s, false);
    } catch (const physics::InvalidInput& e) {
      r.fail("orbits", item + e.what());
    }
    const double off = sim::value_of(p.surface.function, s.omega, s.gamma) - p.surface.value;
    if (!(std::abs(off) <= 1e-9)) {
      char why[160];
      std::snprintf(why, sizeof why, "must start on the surface %s = %g (off it by %.3g)",
                    std::string(sim::name(p.surface.function)).c_str(), p.surface.value, off);
      r.fail("orbits", item + why);
    }
    p.orbits.push_back(s);
  }
}

void write_section_orbits(const scene::SectionPanelSettings& p, Json& j) {
  if (p.orbits.empty()) return;
  Json list = Json::array();
  for (const auto& s : p.orbits)
    list.push_back({{"omega", {s.omega.x(), s.omega.y(), s.omega.z()}},
                    {"gamma", {s.gamma.x(), s.gamma.y(), s.gamma.z()}}});
  j["orbits"] = std::move(list);
}

std::string cloud_members_allowed() {
  std::string s = std::to_string(scene::kMinCloudMembers);
  s += " to ";
  s += std::to_string(scene::kMaxCloudMembers);
  return s;
}

void write_runs(const JobDocument& d, Json& j) {
  if (d.runs.empty()) return;
  Json list = Json::array();
  for (const auto& run : d.runs) {
    Json o = Json::object();
    if (!run.label.empty()) o["label"] = run.label;
    write_entries(simulation_entries(), run.simulation, o);
    if (run.auto_tolerance && !run.simulation.tol) o["tol"] = "auto";
    list.push_back(std::move(o));
  }
  j["runs"] = std::move(list);
}

const std::vector<Job>& job_entries() {
  static const scene::SceneSettings defaults;
  static const std::vector<Job> entries{
      {{"title", ValueType::text, "", "", "overrides the case's title on the overlay"},
       [](io::ObjectReader& r, JobDocument& d) {
         if (auto v = r.string("title")) d.scene.title = *v;
       },
       [](const JobDocument& d, Json& j) {
         if (!d.scene.title.empty()) j["title"] = d.scene.title;
       }},
      {{"simulation", ValueType::object, "", "",
        "what to simulate: the keys of epviz simulate (required)"},
       [](io::ObjectReader& r, JobDocument& d) {
         auto sim = r.object("simulation");
         if (!sim)
           r.fail("simulation",
                  "missing: a render job needs a \"simulation\" object (at least {\"case\": ...})");
         bool auto_tol = false;
         d.simulation = read_simulation_fields(*sim, &auto_tol);
         // Without a "tol" the tolerance follows the resolution, as with "auto".
         d.scene.auto_tolerance = auto_tol || !d.simulation.tol;
         d.scene.formulation_given = d.simulation.formulation.value.has_value();
         sim->finish();
       },
       [](const JobDocument& d, Json& j) {
         Json sim = Json::object();
         write_entries(simulation_entries(), d.simulation, sim);
         if (d.scene.auto_tolerance && !d.simulation.tol && !d.simulation.step) sim["tol"] = "auto";
         j["simulation"] = std::move(sim);
       }},
      {{"runs", ValueType::object, "",
        "an array of 1 to " + std::to_string(max_runs) +
            " objects: \"label\" and any simulation key but t_end and samples",
        "a comparison scene: each run overrides the job's simulation (method, step, tol, "
        "formulation, initial state, body) and all are drawn together, the first solid"},
       read_runs,
       write_runs},
      {{"view", ValueType::choice, "body", "body, space",
        "body: the body fixed, gamma moves; space: the vertical fixed, the body turns"},
       [](io::ObjectReader& r, JobDocument& d) {
         if (auto v = r.choice("view", {"body", "space"}))
           d.scene.view = *v == "space" ? scene::View::space : scene::View::body;
       },
       [](const JobDocument& d, Json& j) {
         j["view"] = d.scene.view == scene::View::space ? "space" : "body";
       }},
      {{"trace_axis", ValueType::integer, "3", "1, 2 or 3",
        "space view: the body axis whose tip the trail follows (2: the tennis-racket flip)"},
       [](io::ObjectReader& r, JobDocument& d) {
         if (auto v = r.integer("trace_axis", 1, 3)) d.scene.trace_axis = int(*v);
       },
       [](const JobDocument& d, Json& j) {
         if (d.scene.trace_axis != 3) j["trace_axis"] = d.scene.trace_axis;
       }},
      {{"overlay_place", ValueType::choice, "auto",
        "auto, beside, top-left, top-right, bottom-left, bottom-right",
        "where the overlay's window goes: auto (beside the 3D view where the panel keeps room, "
        "else over the view clear of the runs' points), beside (always, the panel smaller), or a "
        "corner of the 3D view; a figure at a printed size gives it a band of its own"},
       [](io::ObjectReader& r, JobDocument& d) {
         if (auto v = r.choice("overlay_place", {"auto", "beside", "top-left", "top-right",
                                                 "bottom-left", "bottom-right"}))
           d.scene.page.overlay = *scene::overlay_place_from_name(*v);
       },
       [](const JobDocument& d, Json& j) {
         if (d.scene.page.overlay != scene::OverlayPlace::automatic)
           j["overlay_place"] = std::string(scene::name(d.scene.page.overlay));
       }},
      {{"theme", ValueType::choice, "dark", "dark, light",
        "the colour set; \"colours\" override its defaults"},
       [](io::ObjectReader& r, JobDocument& d) {
         if (auto v = r.choice("theme", {"dark", "light"})) {
           d.scene.theme = *scene::theme_from_name(*v);
           d.scene.colours = scene::theme(d.scene.theme).colours;  // before "colours" is read
         }
       },
       [](const JobDocument& d, Json& j) { j["theme"] = std::string(scene::name(d.scene.theme)); }},
      {{"camera", ValueType::object, "", "", "where the 3D view looks from"},
       {},
       {},
       {
           {{"azimuth", ValueType::number, fmt(defaults.camera.azimuth_deg), "degrees",
             "about the vertical, from +x towards +y"},
            [](io::ObjectReader& r, JobDocument& d) {
              if (auto v = r.number("azimuth")) d.scene.camera.azimuth_deg = *v;
            },
            [](const JobDocument& d, Json& j) { j["azimuth"] = d.scene.camera.azimuth_deg; }},
           {{"elevation", ValueType::number, fmt(defaults.camera.elevation_deg),
             "-90 to 90 (exclusive)", "degrees above the horizontal plane"},
            [](io::ObjectReader& r, JobDocument& d) {
              if (auto v = r.number("elevation")) {
                if (std::abs(*v) >= 90.0)
                  r.fail("elevation", "expected degrees strictly between -90 and 90");
                d.scene.camera.elevation_deg = *v;
              }
            },
            [](const JobDocument& d, Json& j) { j["elevation"] = d.scene.camera.elevation_deg; }},
           {{"distance", ValueType::number, fmt(defaults.camera.distance),
             "more than " + format_number(min_camera_distance) + ", at most " +
                 format_number(max_camera_distance),
             "from the fixed point, in sphere radii"},
            [](io::ObjectReader& r, JobDocument& d) {
              if (auto v = r.positive_number("distance")) {
                if (*v <= min_camera_distance)
                  r.fail("distance", "expected more than " + format_number(min_camera_distance) +
                                         " sphere radii (the camera would be inside the sphere)");
                if (*v > max_camera_distance)
                  r.fail("distance", "expected at most " + format_number(max_camera_distance) +
                                         " sphere radii (the sphere would be a dot), got " +
                                         io::describe(*r.raw("distance")));
                d.scene.camera.distance = *v;
              }
            },
            [](const JobDocument& d, Json& j) { j["distance"] = d.scene.camera.distance; }},
       }},
      {{"layers", ValueType::object, "", "", "what is drawn (at least one)"},
       {},
       {},
       layer_entries(),
       [](const io::ObjectReader& r, const JobDocument& d) {
         if (!d.scene.layers.any())
           r.fail(scene::layer_table().front().key, "every layer is switched off: nothing to draw");
       }},
      {{"colours", ValueType::object, "", "", "colours over the theme's"},
       {},
       {},
       {
           colour("background", &scene::Colours::background, "the picture's background"),
           colour("body", &scene::Colours::body, "the body's faces"),
           colour("sphere", &scene::Colours::sphere, "the glass sphere (alpha: its opacity)"),
           colour("marker", &scene::Colours::marker, "the current point on sphere and plane"),
       }},
      {{"trail", ValueType::object, "", "", "the trail on sphere and plane"},
       {},
       {},
       {
           {{"length", ValueType::number, "", "> 0",
             "simulation time the trail covers (default: the whole run)"},
            [](io::ObjectReader& r, JobDocument& d) {
              if (auto v = r.positive_number("length")) d.scene.trail_length = *v;
            },
            [](const JobDocument& d, Json& j) {
              if (d.scene.trail_length > 0.0) j["length"] = d.scene.trail_length;
            }},
       }},
      {{"cloud", ValueType::object, "", "",
        "an ensemble launched with the run: its members' gamma fill a disc about the run's "
        "gamma, Omega scaled to keep the run's energy; drawn as points on sphere and plane, "
        "with its spread (absent: no cloud)"},
       {},
       {},
       {
           {{"members", ValueType::integer, std::to_string(scene::kDefaultCloudMembers),
             cloud_members_allowed(), "how many states"},
            [](io::ObjectReader& r, JobDocument& d) {
              // Read only when "cloud" is given: absent, the default.
              d.scene.cloud.members =
                  int(r.integer("members", scene::kMinCloudMembers, scene::kMaxCloudMembers)
                          .value_or(scene::kDefaultCloudMembers));
            },
            [](const JobDocument& d, Json& j) {
              if (d.scene.cloud.enabled()) j["members"] = d.scene.cloud.members;
            }},
           {{"radius", ValueType::number, format_number(scene::kDefaultCloudRadius),
             "more than 0, at most " + format_number(scene::kMaxCloudRadius),
             "the disc's angular radius on the sphere, radians"},
            [](io::ObjectReader& r, JobDocument& d) {
              if (auto v = r.positive_number("radius")) {
                if (*v > scene::kMaxCloudRadius)
                  r.fail("radius", "expected more than 0 and at most " +
                                       format_number(scene::kMaxCloudRadius) + " radians, got " +
                                       io::describe(*r.raw("radius")));
                d.scene.cloud.radius = *v;
              }
            },
            [](const JobDocument& d, Json& j) {
              if (d.scene.cloud.enabled()) j["radius"] = d.scene.cloud.radius;
            }},
       }},
      {{"section", ValueType::object, "", "",
        "a Poincaré section panel beside the plane, filling as the run goes: a dot per "
        "crossing of the surface function = value in its direction, at coords; a section "
        "file's keys, defaults and checks (docs/sections.md; absent: no panel)"},
       {},
       {},
       {
           section_key(
               "function", ValueType::choice,
               std::string(sim::name(sim::SectionSurface{}.function)),
               joined(section::state_function_names()), "the state function cut",
               [](io::ObjectReader& r, scene::SectionPanelSettings& p) {
                 section::read_surface_function(r, p.surface);
               },
               [](const scene::SectionPanelSettings& p, Json& j) {
                 j["function"] = sim::name(p.surface.function);
               }),
           section_key(
               "value", ValueType::number, format_number(sim::SectionSurface{}.value),
               section::surface_value_range(), "the level of the function",
               [](io::ObjectReader& r, scene::SectionPanelSettings& p) {
                 section::read_surface_value(r, p.surface);
               },
               [](const scene::SectionPanelSettings& p, Json& j) { j["value"] = p.surface.value; }),
           section_key(
               "direction", ValueType::choice,
               std::string(sim::name(sim::SectionSurface{}.direction)), "upward, downward, both",
               "which sign change of function - value counts",
               [](io::ObjectReader& r, scene::SectionPanelSettings& p) {
                 section::read_surface_direction(r, p.surface);
               },
               [](const scene::SectionPanelSettings& p, Json& j) {
                 j["direction"] = sim::name(p.surface.direction);
               }),
           // After the surface's keys: the axes' default follows the function.
           section_key(
               "coords", ValueType::text, "gamma1, omega3 for a gamma3 surface",
               "an array of two of " + joined(section::state_function_names()),
               "the two state components plotted",
               [](io::ObjectReader& r, scene::SectionPanelSettings& p) {
                 p.coords = section::read_coords(r, p.surface.function);
               },
               [](const scene::SectionPanelSettings& p, Json& j) {
                 j["coords"] = {sim::name(p.coords[0]), sim::name(p.coords[1])};
               }),
           // After the surface's and the axes' keys: the sheet is told apart
           // by a component neither cut nor plotted.
           section_key(
               "sheet", ValueType::text,
               "gamma2 > 0 for a gamma3 surface at gamma1, omega3 (the positive sheet of a "
               "chart with two); none (every crossing) for a chart with one",
               "\"C > 0\" or \"C < 0\", C a state component neither the function nor plotted",
               "the sheet of the surface drawn: its coords cover a surface such as gamma3 = 0 "
               "twice (gamma2 > 0, gamma2 < 0), so the panel draws one and counts the other's "
               "crossings",
               [](io::ObjectReader& r, scene::SectionPanelSettings& p) {
                 if (auto s = section::read_sheet(r, p.surface, p.coords, false))
                   p.sheet = scene::SectionSheet{
                       s->component, s->show == section::SheetChoice::Show::negative ? -1 : 1};
                 else
                   p.sheet = scene::default_sheet(p.surface, p.coords);
               },
               [](const scene::SectionPanelSettings& p, Json& j) {
                 if (p.sheet)
                   j["sheet"] = std::string(sim::name(p.sheet->component)) +
                                (p.sheet->sign > 0 ? " > 0" : " < 0");
               }),
           // After the surface's keys: each start must lie on the surface.
           section_key("orbits", ValueType::text, "none",
                       "an array of up to " + std::to_string(scene::kMaxSectionOrbits) +
                           " objects {\"omega\": [3 numbers], \"gamma\": [3 numbers, unit]} on "
                           "the surface",
                       "further orbits (run as the first run) whose crossings the panel shows, "
                       "each in its own colour; the live mode's clicks on the panel add them",
                       read_section_orbits, write_section_orbits),
       }},
      {{"plane", ValueType::object, "", "", "the Riccati (a, b) panel"},
       {},
       {},
       {
           {{"extent", ValueType::number, fmt(defaults.plane_extent),
             format_number(min_plane_extent) + " to " + format_number(max_plane_extent),
             "the panel shows [-extent, extent]^2"},
            [](io::ObjectReader& r, JobDocument& d) {
              if (auto v = r.number_in("extent", min_plane_extent, max_plane_extent,
                                       "a number from " + format_number(min_plane_extent) + " to " +
                                           format_number(max_plane_extent)))
                d.scene.plane_extent = float(*v);
            },
            [](const JobDocument& d, Json& j) { j["extent"] = d.scene.plane_extent; }},
       }},
      {{"width", ValueType::integer, std::to_string(defaults.width), "16 to 8192",
        "picture width in pixels"},
       [](io::ObjectReader& r, JobDocument& d) {
         if (auto v = r.integer("width", 16, 8192)) d.scene.width = int(*v);
       },
       [](const JobDocument& d, Json& j) { j["width"] = d.scene.width; }},
      {{"height", ValueType::integer, std::to_string(defaults.height), "16 to 8192",
        "picture height in pixels"},
       [](io::ObjectReader& r, JobDocument& d) {
         if (auto v = r.integer("height", 16, 8192)) d.scene.height = int(*v);
       },
       [](const JobDocument& d, Json& j) { j["height"] = d.scene.height; }},
      {{"fps", ValueType::number, fmt(defaults.fps), "> 0, at most 240",
        "frames per second of video"},
       [](io::ObjectReader& r, JobDocument& d) {
         if (auto v = r.positive_number("fps")) {
           if (*v > 240) r.fail("fps", "expected at most 240 frames per second");
           d.scene.fps = *v;
         }
       },
       [](const JobDocument& d, Json& j) { j["fps"] = d.scene.fps; }},
      {{"duration", ValueType::number, fmt(defaults.duration),
        "> 0, fps x duration at most a million",
        "seconds of video; the run's t_end is spread over them"},
       [](io::ObjectReader& r, JobDocument& d) {
         if (auto v = r.positive_number("duration")) d.scene.duration = *v;
         if (d.scene.fps * d.scene.duration > 1e6)
           r.fail("duration", "fps x duration exceeds a million frames");
       },
       [](const JobDocument& d, Json& j) { j["duration"] = d.scene.duration; }},
      {{"output", ValueType::object, "", "", "where and how the frames are written"},
       {},
       {},
       {
           {{"dir", ValueType::text, "out", "a directory", "relative to the current directory"},
            [](io::ObjectReader& r, JobDocument& d) {
              if (auto v = r.string("dir")) d.output.dir = *v;
            },
            [](const JobDocument& d, Json& j) { j["dir"] = d.output.dir.string(); }},
           {{"format", ValueType::choice, "png", joined(output_format_names()),
             "PNG frames or a video"},
            [](io::ObjectReader& r, JobDocument& d) {
              if (auto v = r.choice("format", output_format_names()))
                d.output.video = io::parse_video_format(*v);  // png: none
            },
            [](const JobDocument& d, Json& j) {
              j["format"] = std::string(output_format_name(d.output.video));
            }},
           {{"name", ValueType::text, "frame (png), the job file's name (video)",
             "a file name without '/'", "PNG frame prefix or video file stem"},
            [](io::ObjectReader& r, JobDocument& d) {
              if (auto v = r.string("name")) {
                if (v->empty() || v->find('/') != std::string::npos)
                  r.fail("name", "expected a file name without '/'");
                d.output.name = *v;
              }
            },
            [](const JobDocument& d, Json& j) {
              if (!d.output.name.empty()) j["name"] = d.output.name;
            }},
           {{"figure_width", ValueType::text, "none (a screen picture)",
             "a length from 1in to 20in: 85mm, 8.5cm, 3.5in, 241pt",
             "a figure for print this wide, its text at font_size, its parts stacked (as "
             "--figure-width)"},
            [](io::ObjectReader& r, JobDocument& d) {
              if (auto v = r.string("figure_width")) {
                (void)io::parse_length_pt(r.where("figure_width"), *v);
                d.output.print.width = *v;
              }
            },
            [](const JobDocument& d, Json& j) {
              if (!d.output.print.width.empty()) j["figure_width"] = d.output.print.width;
            }},
           {{"font_size", ValueType::number, "8", "5 to 24",
             "with figure_width: the text's size in points"},
            [](io::ObjectReader& r, JobDocument& d) {
              if (auto v = r.number_in("font_size", io::kMinFontPt, io::kMaxFontPt,
                                       "a size in points from 5 to 24"))
                d.output.print.font = fmt(*v);
            },
            [](const JobDocument& d, Json& j) {
              if (!d.output.print.font.empty()) j["font_size"] = std::stod(d.output.print.font);
            }},
           {{"dpi", ValueType::number, "300", "72 to 1200",
             "with figure_width: pixels per inch of PNG frames and of an SVG or PDF's 3D view"},
            [](io::ObjectReader& r, JobDocument& d) {
              if (auto v = r.number_in("dpi", io::kMinDpi, io::kMaxDpi, "a number from 72 to 1200"))
                d.output.print.dpi = fmt(*v);
            },
            [](const JobDocument& d, Json& j) {
              if (!d.output.print.dpi.empty()) j["dpi"] = std::stod(d.output.print.dpi);
            }},
       }},
  };
  return entries;
}

}  // namespace

void SimulationFields::overlay(const SimulationFields& o) {
  for (const auto& info : simulation_field_table())
    std::visit(
        [&](auto m) {
          if (o.*m) this->*m = o.*m;
        },
        info.member);
}

std::vector<std::string> output_format_names() {
  std::vector<std::string> names{"png"};
  for (const auto f : io::video_formats) names.emplace_back(io::video_format_name(f));
  return names;
}

std::string_view output_format_name(const std::optional<io::VideoFormat>& video) {
  return video ? io::video_format_name(*video) : "png";
}

std::optional<io::VideoFormat> parse_output_format(const std::string& option,
                                                   const std::string& name) {
  const auto names = output_format_names();
  if (std::find(names.begin(), names.end(), name) == names.end())
    throw io::BadInput(option + ": unknown format '" + io::printable(name) +
                       "' (allowed: " + joined(names) + ")");
  return io::parse_video_format(name);
}

std::string hex_colour(const scene::Rgba& c) {
  auto byte = [](float x) { return int(std::lround(std::clamp(x, 0.0f, 1.0f) * 255.0f)); };
  char buf[16];
  std::snprintf(buf, sizeof buf, "#%02x%02x%02x%02x", byte(c[0]), byte(c[1]), byte(c[2]),
                byte(c[3]));
  return buf;
}

std::vector<KeyInfo> render_job_keys() {
  std::vector<KeyInfo> keys;
  for (const auto& e : job_entries()) {
    keys.push_back(e.info);
    if (e.info.path == "simulation") list_keys(simulation_entries(), "simulation.", keys);
    list_keys(e.children, e.info.path + ".", keys);
  }
  return keys;
}

SimulationFields read_simulation_fields(io::ObjectReader& r, bool* auto_tol) {
  SimulationFields f;
  if (auto_tol) {
    *auto_tol = r.peek_string("tol") == std::optional<std::string>("auto");
    if (*auto_tol) r.mark_read("tol");
  }
  for (const auto& e : simulation_entries())
    if (!(auto_tol && *auto_tol && e.info.path == "tol")) e.read(r, f);
  return f;
}

JobDocument read_job(const nlohmann::json& object, const std::string& file) {
  JobDocument d;
  io::ObjectReader r(object, file);
  read_entries(job_entries(), r, d);
  r.finish();
  return d;
}

Json write_job(const JobDocument& job) {
  Json j = Json::object();
  write_entries(job_entries(), job, j);
  return j;
}

std::string entries::joined(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : ", ") + x;
  return s;
}

}  // namespace epviz::job
