#include "io/hydrodynamic_models.hpp"

#include <cmath>
#include <stdexcept>

#include "coupling/fcm_model.hpp"
#include "dem/integrate/pairwise_models.hpp"
#include "io/case.hpp"

namespace suspend::io {

namespace {
// The pairwise engine: Stokes drag, pairwise lubrication solved or explicit (dem/integrate/pairwise_models.hpp).
const HydrodynamicModelEntry pairwise{
    "pairwise",
    [](const Case& c) { return c.simulation.lubrication; },
    [](const Case& c) { check_pairwise_model(c.simulation); },
    [](const Case&, YAML::Node&) {},
    [](SimulationState state, const Box& box, const Case& c) {
      return Simulation(std::move(state), box, c.simulation);
    },
    [](const Simulation&, nlohmann::json&) {},
    [](const Case& c) {
      return c.simulation.lubrication && c.simulation.resistance.lubrication.exact_relative
                 ? std::string("exact_relative lubrication")
                 : std::string();
    },
    [](const Case&, const Vec3&, double) { return 0.0; }};

// FCM with its sub-grid lubrication (coupling/fcm_model.hpp).
const HydrodynamicModelEntry fcm{
    "fcm",
    [](const Case& c) { return c.fcm.subgrid; },
    [](const Case& c) { FcmModel::check(c.simulation, c.fcm); },
    [](const Case& c, YAML::Node& h) {
      YAML::Node m = h["fcm"];
      m["grid_spacing"] = number_node(c.fcm.grid_spacing);
      m["truncation_widths"] = number_node(c.fcm.truncation_widths);
      m["tolerance"] = number_node(c.fcm.krylov_tolerance);
      m["max_iterations"] = c.fcm.max_iterations;
      m["far_field_every"] = c.fcm.far_field_every;
      m["predictor"] = c.fcm.lagged_predictor ? "lagged_far_field" : "extrapolated";
      m["preconditioner_iterations"] = c.fcm.preconditioner_iterations;
      m["lagged_cutoff"] = number_node(c.fcm.lagged_cutoff);
      m["lagged_tolerance"] = number_node(c.fcm.lagged_tolerance);
      m["subgrid"] = c.fcm.subgrid;
      m["subgrid_cutoff"] = number_node(c.fcm.subgrid_cutoff);
      m["cache_dir"] = c.fcm.cache_dir;
    },
    [](SimulationState state, const Box& box, const Case& c) {
      return fcm_simulation(std::move(state), box, c.simulation, c.fcm);
    },
    [](const Simulation& sim, nlohmann::json& summary) {
      const FcmModel& m = fcm_model(sim);
      const auto steps = m.evaluated_steps(), solves = m.total_stokes_solves();
      summary["fcm"] = {{"steps", steps}, {"stokes_solves", solves},
                        {"stokes_solves_per_step", steps > 0 ? static_cast<double>(solves) / steps : 0.0}};
    },
    [](const Case& c) { return c.fcm.subgrid ? std::string("sub-grid correction") : std::string(); },
    [](const Case& c, const Vec3& box_lengths, double smallest_radius) {
      const double h = c.fcm.grid_spacing > 0.0 ? c.fcm.grid_spacing : 0.5 * smallest_radius;
      double nodes = 1.0;
      for (int a = 0; a < 3; ++a) nodes *= std::ceil(box_lengths[a] / h);
      return nodes;
    }};
}  // namespace

const std::vector<HydrodynamicModelEntry>& hydrodynamic_models() {
  static const std::vector<HydrodynamicModelEntry> all = {pairwise, fcm};
  return all;
}

std::vector<std::string> hydrodynamic_model_names() {
  std::vector<std::string> names;
  for (const HydrodynamicModelEntry& m : hydrodynamic_models()) names.emplace_back(m.name);
  return names;
}

const HydrodynamicModelEntry& hydrodynamic_model(const std::string& name) {
  for (const HydrodynamicModelEntry& m : hydrodynamic_models())
    if (name == m.name) return m;
  throw std::logic_error("hydrodynamics.model '" + name + "' is not registered");
}

}  // namespace suspend::io
