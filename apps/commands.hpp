// One function per subcommand of the `suspend` program; each lives in its own apps/cmd_*.cpp.
#pragma once
#include <CLI/CLI.hpp>

namespace suspend::app {
void add_run_command(CLI::App& app);
void add_check_command(CLI::App& app);
// `suspend pair`: two-sphere resistance functions of the lubrication model (apps/cmd_pair.cpp).
void add_pair_command(CLI::App& app);
// suspend mobility: FCM velocities, angular velocities and stresslets of spheres in a periodic box.
void add_mobility_command(CLI::App& app);
// `suspend crossval`: one case with both hydrodynamic models, side by side (apps/cmd_crossval.cpp).
void add_crossval_command(CLI::App& app);
// `suspend sweep`: the points of a campaign, resumable (apps/cmd_sweep.cpp).
void add_sweep_command(CLI::App& app);
// `suspend phim`: Maron-Pierce fits of phi_m(sigma*) to a campaign table (apps/cmd_phim.cpp).
void add_phim_command(CLI::App& app);
// `suspend analyze`: contact network, clusters, fabric and distributions of a run's snapshots (apps/cmd_analyze.cpp).
void add_analyze_command(CLI::App& app);
// `suspend export`: snapshots as extended XYZ or GSD, through python/suspend/export.py (apps/cmd_export.cpp).
void add_export_command(CLI::App& app);
}  // namespace suspend::app
