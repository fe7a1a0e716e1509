// `suspend check CASE.yaml [--set KEY=VALUE]...`: validate and print the fully resolved case without running.
#include <cstdio>
#include <iostream>
#include <sstream>

#include "apps/commands.hpp"
#include "io/case.hpp"
#include "io/exact_tables.hpp"
#include "io/initial_configuration.hpp"

namespace suspend::app {

void add_check_command(CLI::App& app) {
  struct Options {
    std::string case_file;
    std::vector<std::string> overrides;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand("check", "Validate a case and print it with every default and derived value");
  cmd->add_option("case", opt->case_file, "case file (YAML, see docs/cases.md)")->required();
  cmd->add_option("--set,-s", opt->overrides, "override a case key by its dotted path")->take_all();
  cmd->callback([opt] {
    const io::Case c = io::load_case(opt->case_file, opt->overrides);
    // The derived values first: a case that cannot be built is refused before anything is printed.
    std::ostringstream derived;
    char line[256];
    if (c.particles.initial == "random") {
      const io::Composition k = io::composition_of(c);
      derived << "particles: " << k.radius.size() << "  # per species:";
      for (std::size_t s = 0; s < k.counts.size(); ++s)
        derived << " " << k.counts[s] << " of radius " << c.particles.species[s].radius;
      derived << "\n";
      std::snprintf(line, sizeof line, "box: [%.6g, %.6g, %.6g]\nphi: %.6g  # requested %.6g\n", k.box.length().x(),
                    k.box.length().y(), k.box.length().z(), k.phi, c.particles.phi);
    } else {
      const io::InitialConfiguration ic = io::build_initial_configuration(c);
      derived << "particles: " << ic.particles.size() << "  # " << ic.origin << "\n";
      std::snprintf(line, sizeof line, "box: [%.6g, %.6g, %.6g]\nphi: %.6g\n", ic.box.length().x(),
                    ic.box.length().y(), ic.box.length().z(), ic.phi);
    }
    derived << line;
    std::cout << "# " << c.source << ": valid\n" << io::to_yaml_text(c) << "\n";
    std::cout << "# derived\n";
    for (const std::string& note : io::exact_table_notes(c)) std::cout << "# note: " << note << "\n";
    std::cout << derived.str();
  });
}

}  // namespace suspend::app
