// The hydrodynamic models a case can name (hydrodynamics.model): one entry each in hydrodynamic_models.cpp, with
// what the rest of the program asks of a model by name: whether its overdamped solve can take implicit contact
// springs, the refusals of what it cannot do, its keys in the resolved case, the simulation it builds, its block in
// summary.json, which of its terms use the exact two-sphere tables and the size of its grid. Adding a model is its
// HydrodynamicModel (dem/hydrodynamic_model.hpp) plus its entry here (docs/architecture.md).
#pragma once
#include <yaml-cpp/yaml.h>

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "dem/simulation.hpp"

namespace suspend::io {

struct Case;

struct HydrodynamicModelEntry {
  const char* name;
  // Implicit contact springs need the model's overdamped resistance solve (docs/overdamped.md 4b).
  bool (*takes_implicit_contacts)(const Case&);
  // InputError naming the key of what the model cannot do with this case.
  void (*check)(const Case&);
  // Its own keys in the resolved case, under `hydrodynamics` (beside the lubrication and solver blocks every case
  // carries, so one case file serves `suspend crossval`).
  void (*write)(const Case&, YAML::Node& hydrodynamics);
  Simulation (*build)(SimulationState state, const Box& box, const Case&);
  // Its entries in summary.json (FCM: the Stokes solves per step).
  void (*summarise)(const Simulation&, nlohmann::json& summary);
  // The terms that use the exact two-sphere tables with this case ("" when none).
  std::string (*exact_table_user)(const Case&);
  // The nodes of its grid for a box of these sides (0 without a grid), for the memory estimate before a run.
  double (*grid_nodes)(const Case&, const Vec3& box_lengths, double smallest_radius);
};

const std::vector<HydrodynamicModelEntry>& hydrodynamic_models();
std::vector<std::string> hydrodynamic_model_names();
// The entry of a registered name (the case reader only lets those through).
const HydrodynamicModelEntry& hydrodynamic_model(const std::string& name);

}  // namespace suspend::io
