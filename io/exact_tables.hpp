// Which species pairs of a case cannot have an exact near field: the exact two-sphere tables exist for the size
// ratios 1, 1.4 and 1/1.4 only (dem/hydro/exact_remainder.hpp). Where a case asks for exact functions (the FCM
// sub-grid correction, or the pairwise `lubrication.functions: exact_relative`), the other pairs keep the singular
// model; the run and `suspend check` say so with these notes.
#pragma once
#include <string>
#include <vector>

#include "io/case.hpp"

namespace suspend::io {

// One line per species pair without an exact table, empty when every pair has one or none is asked for.
std::vector<std::string> exact_table_notes(const Case& c);

}  // namespace suspend::io
