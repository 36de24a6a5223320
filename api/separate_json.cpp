// The JSON form of a separation (api/separate_json.hpp).
#include "api/separate_json.hpp"

#include "kernel/answer.hpp"

namespace eccd {

namespace {

std::vector<std::string> strings_of(const std::vector<mpq_class>& v, bool exact) {
  std::vector<std::string> r;
  for (const auto& x : v) r.push_back(exact ? x.get_str() : decimal_string(x, 20));
  return r;
}

}  // namespace

nlohmann::ordered_json separation_to_json(const Scene& scene, const std::string& file, const mpq_class& t,
                                          const Arithmetic& arith, const Separation& sep) {
  const bool exact = !arith.floating();
  nlohmann::ordered_json j;
  j["scene"] = scene.name;
  j["file"] = file;
  j["dim"] = scene.dim;
  j["arith"] = arith.name();
  j["t"] = t.get_str();
  j["status"] = sep.status;
  if (sep.plane) {
    nlohmann::ordered_json pl;
    pl["normal"] = strings_of(sep.plane->normal, true);
    pl["offset"] = sep.plane->offset.get_str();
    pl["meaning"] = "n.x + o = 0; object a in n.x + o < 0, object b in n.x + o > 0";
    j["plane"] = pl;
    nlohmann::ordered_json tp = nlohmann::ordered_json::array();
    for (const auto& p : sep.tangent_points) tp.push_back(strings_of(p, false));
    j["tangent_points"] = tp;
    j["tangent_points_note"] = "000 section 3: P_R^A on a and P_L^B on b, decimals (irrational in general)";
  }
  if (!sep.checks.empty()) {
    nlohmann::ordered_json ch = nlohmann::ordered_json::array();
    for (const auto& k : sep.checks) {
      nlohmann::ordered_json x;
      x["object"] = k.object;
      x["quantity"] = k.quantity;
      x["relation"] = k.relation;
      x["value"] = exact ? k.value.get_str() : decimal_string(k.value, 17);
      if (!exact) x["error_bound"] = k.error_bound;
      if (!k.centre.empty()) x["centre"] = strings_of(k.centre, exact);
      ch.push_back(x);
    }
    j["checks"] = ch;
    j["checks_note"] =
        exact ? "exact rationals: q = M(t)^T (n, o) with M(t) the scene's motion matrix and Q its shape matrix; "
                "q^T adj(Q) q > 0 iff the plane misses the object (det Q < 0)"
              : "computed in " + arith.name() + " with a running error bound";
  }
  if (!sep.why.empty()) j["why"] = sep.why;
  return j;
}

}  // namespace eccd
