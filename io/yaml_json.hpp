// A YAML tree as JSON (summary.json's `case`): maps and sequences keep their shape, scalars become integers,
// numbers or booleans when they read as such, strings otherwise.
#pragma once
#include <yaml-cpp/yaml.h>

#include <nlohmann/json.hpp>

namespace suspend::io {

nlohmann::ordered_json yaml_to_json(const YAML::Node& node);

}  // namespace suspend::io
