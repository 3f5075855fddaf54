// A soil as YAML names it (terrain files' materials, wtc-mobility's ground).
#include "soil_node.hpp"

#include <optional>
#include <string>

#include "wtc/base/error.hpp"

namespace wtc::io::detail {

// `soil: name` (a shipped soil) or a map of its fields, `base: name` first
// when it only changes some of a shipped soil's.
Soil readSoil(const YamlReader& in, const YAML::Node& node) {
  auto shipped = [&](const YAML::Node& name_node) {
    const std::string name = in.string(name_node, "soil");
    std::optional<Soil> found = namedSoil(name);
    if (!found) {
      std::string known;
      for (const std::string& n : soilNames()) known += (known.empty() ? "" : ", ") + n;
      in.fail(name_node, "unknown soil '" + name + "' (shipped: " + known + ")");
    }
    return *found;
  };
  if (!node.IsMap()) return shipped(node);
  in.checkKeys(node, {"base", "name", "k_c", "k_phi", "n", "cohesion", "friction_angle_deg", "shear_modulus_x",
                      "shear_modulus_y", "a0", "a1", "unloading_stiffness", "damping", "density", "rebound_ratio"});
  Soil soil;
  if (const auto base = YamlReader::get(node, "base")) soil = shipped(*base);
  if (const auto name = YamlReader::get(node, "name")) soil.name = in.string(*name, "name");
  if (soil.name.empty()) soil.name = "custom";
  for (const SoilField& f : soilFields()) soil.*f.member = in.number(node, f.name, soil.*f.member);
  try {
    validate(soil, "soil");
  } catch (const InvalidInputError& e) {
    in.fail(node, e.what());
  }
  return soil;
}

}  // namespace wtc::io::detail
