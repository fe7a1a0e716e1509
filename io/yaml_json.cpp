#include "io/yaml_json.hpp"

#include <cstdint>
#include <string>

namespace suspend::io {

namespace {

nlohmann::ordered_json scalar(const YAML::Node& node) {
  const std::string& text = node.Scalar();
  if (node.Tag() == "!") return text;  // quoted in the YAML: a string whatever it looks like
  std::int64_t i = 0;
  if (YAML::convert<std::int64_t>::decode(node, i) && text.find_first_of(".eE") == std::string::npos) return i;
  double d = 0.0;
  if (YAML::convert<double>::decode(node, d)) return d;
  bool b = false;
  if (YAML::convert<bool>::decode(node, b)) return b;
  if (text == "~" || text == "null") return nullptr;
  return text;
}

}  // namespace

nlohmann::ordered_json yaml_to_json(const YAML::Node& node) {
  switch (node.Type()) {
    case YAML::NodeType::Map: {
      nlohmann::ordered_json j = nlohmann::ordered_json::object();
      for (const auto& kv : node) j[kv.first.as<std::string>()] = yaml_to_json(kv.second);
      return j;
    }
    case YAML::NodeType::Sequence: {
      nlohmann::ordered_json j = nlohmann::ordered_json::array();
      for (const auto& v : node) j.push_back(yaml_to_json(v));
      return j;
    }
    case YAML::NodeType::Scalar:
      return scalar(node);
    default:
      return nullptr;
  }
}

}  // namespace suspend::io
