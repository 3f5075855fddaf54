// A material as YAML gives it (terrain files' materials, wtc-mobility's ground).
#include "material_node.hpp"

#include "soil_node.hpp"
#include "wtc/base/error.hpp"
#include "wtc/tyre/traction_law.hpp"

namespace wtc::io::detail {

Material readMaterial(const YamlReader& in, const YAML::Node& node, const std::string& name) {
  in.requireMap(node, "a material");
  in.checkKeys(node, {"mu_max", "s1", "s2", "mu_peak", "rolling_resistance", "soil"});
  Material material;
  material.name = name;
  material.mu_max = in.number(node, "mu_max", material.mu_max);
  material.s1 = in.number(node, "s1", material.s1);
  material.s2 = in.number(node, "s2", material.s2);
  // A static coefficient (the peak of mu(s)) instead of s2: the spec's
  // mapping of a static/dynamic pair onto the slip law.
  if (const auto peak = YamlReader::get(node, "mu_peak")) {
    if (YamlReader::get(node, "s2")) in.fail(*peak, "give either s2 or mu_peak, not both");
    const double mu_peak = in.number(*peak, "mu_peak");
    if (!(mu_peak > material.mu_max)) {
      in.fail(*peak, "mu_peak " + formatNumber(mu_peak) + " must exceed mu_max " + formatNumber(material.mu_max));
    }
    material.s2 = adhesionBoostForPeakRatio(mu_peak / material.mu_max);
  }
  material.rolling_resistance = in.number(node, "rolling_resistance", material.rolling_resistance);
  if (const auto soil = YamlReader::get(node, "soil")) material.soil = readSoil(in, *soil);
  return material;
}

}  // namespace wtc::io::detail
