// `suspend analyze`'s record of one configuration as JSON (docs/output.md, "Microstructure"): the contact
// numbers, clusters, tensors and distributions of contact_network.hpp, contact_stress.hpp and distributions.hpp,
// and the profiles across the gradient direction of gradient_profile.hpp.
#pragma once
#include <nlohmann/json.hpp>

#include "analysis/configuration.hpp"

namespace suspend::analysis {

struct ReportOptions {
  bool distributions = true;  // forces, gaps, g(r) and g(x, y); false: the scalars, tensors and clusters only
  int profile_bins = 8;       // slabs across y of the gradient profile (gradient_profile.hpp)
};
nlohmann::ordered_json report(const Configuration& c, const ReportOptions& options = {});

}  // namespace suspend::analysis
