#pragma once
// `epviz diagram --sections`: for each region of the diagram
// (app/diagram_regions.hpp), orbits on the level of the region's point
// (C1, C0 and the fourth integral all fixed) and their Poincaré section, run
// by the section engine (section/section_run.hpp) as `epviz section` runs a
// section file's orbits.
#include <string>
#include <vector>

#include "app/diagram_regions.hpp"
#include "chart/chart_spec.hpp"
#include "physics/critical_values.hpp"
#include "section/section_job.hpp"
#include "section/section_run.hpp"

namespace epviz::app {

// Up to `count` states with C1 = point.energy, C0 = area, |γ| = 1 and the
// fourth integral = point.integral, each within 1e-12 of its scale
// (physics::invariant_scales): states of the level (physics::level_states,
// 4000 directions of γ) whose integral is nearest, moved onto the value by
// least-norm Newton steps on the four conditions; of those that converge,
// `count` spread apart (each the farthest from the ones taken), so that the
// several tori of one value each get an orbit. Empty when none converges.
std::vector<physics::InitialState> region_starts(const physics::DiagramRequest& request,
                                                 const physics::ValuePoint& point, int count);

// The section the region's orbits are run on, as a section file would give
// it: the surface `surface` (0: γ₃ = 0 upward, axes (γ₁, Ω₃), the sheets
// γ₂ > 0 and γ₂ < 0 in panels of their own, as the shipped sections; 1 and
// 2 its cyclic turns: γ₁ = 0 with (γ₂, Ω₁) by γ₃, γ₂ = 0 with (γ₃, Ω₂) by
// γ₁), dop853 at tol 1e-10, `crossings` per orbit (at most, by t = 1e4); the
// CSV `csv`.
section::SectionJob region_section_job(const physics::DiagramRequest& request,
                                       std::vector<physics::InitialState> starts, int crossings,
                                       const std::string& csv, int surface);

// The first of the three surfaces that every orbit of `starts` crosses three
// times by t = 200 (a fast top whose axis 3 never dips below the horizontal
// never crosses γ₃ = 0), else the one crossed most, found by running the
// section engine on them.
int region_surface(const physics::DiagramRequest& request,
                   const std::vector<physics::InitialState>& starts, int threads);

// The picture "section_<label>.png": the section's panels under a title that
// names the region and its point.
chart::Figure region_section_figure(const physics::DiagramRequest& request,
                                    const DiagramRegion& region, const section::SectionJob& job,
                                    const std::vector<section::OrbitResult>& orbits);

}  // namespace epviz::app
