// The needle family of scenes: compare/needle_family.hpp.
#include "compare/needle_family.hpp"

#include <stdexcept>

namespace eccd {

GeneratedScene needle_scene(const NeedleSpec& sp) {
  if (sp.dim != 2 && sp.dim != 3) throw std::invalid_argument("needle: dim must be 2 or 3");
  if (sp.r_exponent < 0 || sp.r_exponent > 300) throw std::invalid_argument("needle: R = 10^k needs 0 <= k <= 300");
  if (sp.kind == "miss" && sp.gap_exponent < 1) throw std::invalid_argument("needle: the gap 10^-k needs k >= 1");
  using J = nlohmann::ordered_json;
  const std::string R = "1e" + std::to_string(sp.r_exponent);
  J x;  // the centre's x(t), power basis
  std::string name;
  GeneratedScene g;
  g.spec.dim = sp.dim;
  g.spec.family = "needle";
  g.spec.degree = sp.kind == "touch-end" ? 1 : 2;
  g.spec.motion = sp.dim == 3 ? "euler" : "matrix";
  if (sp.kind == "miss") {
    x = J::array({"-3." + std::string(std::size_t(sp.gap_exponent - 1), '0') + "1", "4", "-4"});
    name = "needle-" + std::to_string(sp.dim) + "d-R1e" + std::to_string(sp.r_exponent) + "-miss1e-" +
           std::to_string(sp.gap_exponent);
    g.spec.d_exponent = sp.gap_exponent;
    g.t0 = Rational(1, 2);
  } else if (sp.kind == "touch-end") {
    x = J::array({"-3", "1"});
    name = "needle-" + std::to_string(sp.dim) + "d-R1e" + std::to_string(sp.r_exponent) + "-touch-end";
    g.t0 = Rational(1);
  } else if (sp.kind == "touch-mid") {
    x = J::array({"-3", "4", "-4"});
    name = "needle-" + std::to_string(sp.dim) + "d-R1e" + std::to_string(sp.r_exponent) + "-touch-mid";
    g.t0 = Rational(1, 2);
  } else {
    throw std::invalid_argument("needle: unknown kind '" + sp.kind + "' (miss, touch-end, touch-mid)");
  }
  J doc;
  doc["format"] = "ellipse-ccd-scene/1";
  doc["name"] = name;
  doc["dim"] = sp.dim;
  if (sp.dim == 3) {
    doc["a"] = {{"shape", {{"semi_axes", J::array({"1", "1", "1"})}}}, {"motion", {{"type", "static"}}}};
    doc["b"] = {{"shape", {{"semi_axes", J::array({"1", R, "1"})}}},
                {"motion",
                 {{"type", "euler"},
                  {"e", J::array({"1", "0", "0", "0"})},
                  {"translation", J::array({x, "0", "0"})},
                  {"translation_denominator", "1"}}}};
  } else {
    doc["a"] = {{"shape", {{"semi_axes", J::array({"1", "1"})}}}, {"motion", {{"type", "static"}}}};
    doc["b"] = {{"shape", {{"semi_axes", J::array({"1", R})}}},
                {"motion",
                 {{"type", "matrix"},
                  {"m", J::array({J::array({"1", "0", x}), J::array({"0", "1", "0"}), J::array({"0", "0", "1"})})}}}};
  }
  doc["note"] = "Needle family (compare/needle_family.hpp): a static unit " +
                std::string(sp.dim == 3 ? "sphere" : "circle") + " and a needle of semi-axes (1, " + R +
                (sp.dim == 3 ? ", 1)" : ")") + " whose centre moves along x: " +
                (sp.kind == "miss"
                     ? "closest at t = 1/2 with a gap of 1e-" + std::to_string(sp.gap_exponent) + ", never touching."
                 : sp.kind == "touch-end" ? "one external touch at t = 1."
                                          : "one tangential touch at t = 1/2.");
  g.name = name;
  g.doc = doc;
  return g;
}

std::vector<NeedleSpec> needle_family_plan() {
  std::vector<NeedleSpec> out;
  for (int dim : {2, 3})
    for (int r : {0, 5, 20, 50, 100, 200, 300}) {
      for (int gap : {3, 6, 9, 12}) out.push_back({dim, r, "miss", gap});
      out.push_back({dim, r, "touch-end", 0});
      out.push_back({dim, r, "touch-mid", 0});
    }
  return out;
}

}  // namespace eccd
