// `suspend check CASE.yaml [--set KEY=VALUE]...`: validate and print the fully resolved case without running.
#include <cstdio>
#include <iostream>

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
    std::cout << "# " << c.source << ": valid\n" << io::to_yaml_text(c) << "\n";
    std::cout << "# derived\n";
    for (const std::string& note : io::exact_table_notes(c)) std::cout << "# note: " << note << "\n";
    if (c.particles.initial == "random") {
      const io::Composition k = io::composition_of(c);
      std::cout << "particles: " << k.radius.size() << "  # per species:";
      for (std::size_t s = 0; s < k.counts.size(); ++s)
        std::cout << " " << k.counts[s] << " of radius " << c.particles.species[s].radius;
      std::cout << "\n";
      std::printf("box: [%.6g, %.6g, %.6g]\nphi: %.6g  # requested %.6g\n", k.box.length().x(), k.box.length().y(),
                  k.box.length().z(), k.phi, c.particles.phi);
    } else {
      const io::InitialConfiguration ic = io::build_initial_configuration(c);
      std::printf("particles: %zu  # %s\nbox: [%.6g, %.6g, %.6g]\nphi: %.6g\n", ic.particles.size(),
                  ic.origin.c_str(), ic.box.length().x(), ic.box.length().y(), ic.box.length().z(), ic.phi);
    }
  });
}

}  // namespace suspend::app
