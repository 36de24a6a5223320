// The mutation campaign (docs/checking.md): genuine certificates mutated at
// random (seed printed) and given to both checkers of eccd-certificate/2, the
// independent one (certificate/check/, eccd-check's library) and the one on
// the prover's algebra (certificate/write/prover_self_check.hpp). Mutations: collides
// flipped, an end moved, an interval or a root dropped or added, an integer
// changed by one, the scene swapped, a key duplicated, a bracket widened past
// its neighbour, a status or an evidence sign flipped, a gap point dropped.
// No mutation that changes the answer (or the scene, or duplicates a key) may
// be VALID in either checker; a VALID mutant must leave the answer as it was
// (e.g. a gap point moved inside its gap). [mutation]: 500 per kind per run;
// [.long][mutation-long]: 10^5 per kind (hidden, run by hand). ECCD_MUTATION_SEED fixes the
// seed.
#include "certificate/check/verdict.hpp"
#include "certificate/write/exact_certificate.hpp"
#include "certificate/check_certificate.hpp"
#include "certificate/write/prover_self_check.hpp"
#include "io/scene_reader.hpp"
#include "tests/support/certificate_mutation.hpp"

#include <catch2/catch.hpp>

#include <cstdlib>
#include <functional>
#include <iostream>
#include <random>

namespace ECCD_UNITY_ID {
using namespace eccd;
using json = nlohmann::json;

namespace {

const std::string src = ECCD_SOURCE_DIR;

struct Base {
  std::string name, scene_path, scene_text, other_scene_text;
  Scene scene;
  json doc, cert;
};

Base base(const std::string& name, const std::string& rel, const std::string& other_rel) {
  Base b;
  b.name = name;
  b.scene_path = src + "/cases/" + rel;
  b.scene_text = read_file_bytes(b.scene_path);
  b.other_scene_text = read_file_bytes(src + "/cases/" + other_rel);
  b.scene = parse_scene(b.scene_text, b.scene_path);
  b.doc = parse_json_document(b.scene_text, b.scene_path);
  b.cert = make_certificate(b.scene, b.doc);
  return b;
}

using eccd::test::collect;

using eccd::test::is_rational_text;

std::string plus_one(const std::string& s, int d) {
  const std::size_t slash = s.find('/');
  mpz_class n(slash == std::string::npos ? s : s.substr(0, slash), 10);
  n += d;
  return n.get_str() + (slash == std::string::npos ? "" : s.substr(slash));
}

using eccd::test::Mutant;

Mutant mutate(const Base& b, std::mt19937_64& rng) {
  auto pick = [&](std::size_t n) { return std::size_t(std::uniform_int_distribution<std::size_t>(0, n - 1)(rng)); };
  json c = b.cert;
  Mutant m;
  m.scene_text = b.scene_text;
  json& tl = c["timeline"];
  const bool has_timeline = tl.is_array() && tl.size() >= 3;
  switch (pick(11)) {
    case 0:
      m.what = "collides flipped";
      c["answer"]["collides"] = !c["answer"]["collides"].get<bool>();
      break;
    case 1: {  // an end moved: a bracket end of the timeline or of the answer
      std::vector<json::json_pointer> ends;
      collect(
          c, json::json_pointer(),
          [](const json& j) { return j.is_object() && j.contains("lo") && j.contains("hi") && j.contains("approx"); },
          ends);
      const auto p = ends[pick(ends.size())];
      json& in = c[p];
      const char* key = pick(2) ? "lo" : "hi";
      mpq_class lo(in["lo"].get<std::string>()), hi(in["hi"].get<std::string>());
      lo.canonicalize();
      hi.canonicalize();
      mpq_class w = hi - lo;
      if (w == 0) w = mpq_class(1, 1 << 20);
      const mpq_class shift[] = {w / 2, -w / 2, w * 2, -w * 2, mpq_class(1, 1000), mpq_class(-1, 1000)};
      mpq_class v = (key[0] == 'l' ? lo : hi) + shift[pick(6)];
      in[key] = v.get_str();
      m.what = std::string("end moved: ") + p.to_string() + "/" + key;
      m.may_stay_valid =
          p.to_string().rfind("/timeline", 0) == 0;  // a wider or narrower bracket may still prove the same root
      break;
    }
    case 2: {  // an interval dropped or added
      json& iv = c["answer"]["intervals"];
      if (!iv.empty() && pick(2)) {
        iv.erase(iv.begin() + long(pick(iv.size())));
        m.what = "interval dropped";
      } else {
        iv.push_back(
            json::array({{{"approx", "1"}, {"lo", "1"}, {"hi", "1"}}, {{"approx", "1"}, {"lo", "1"}, {"hi", "1"}}}));
        m.what = "interval added";
      }
      break;
    }
    case 3: {  // a root dropped or added (an instant and its cell)
      if (!has_timeline || tl.size() < 5 || pick(2)) {
        if (!has_timeline) {
          c["answer"]["contacts"].push_back({{"approx", "0.5"}, {"lo", "1/2"}, {"hi", "1/2"}});
          m.what = "contact added";
          break;
        }
        const std::size_t k = 1 + 2 * pick(tl.size() / 2);  // a cell
        json cell = tl[k], inst = tl[k - 1];
        tl.insert(tl.begin() + long(k), cell);
        tl.insert(tl.begin() + long(k) + 1, inst);
        m.what = "root added (an instant and a cell duplicated)";
      } else {
        const std::size_t k = 2 + 2 * pick((tl.size() - 3) / 2);  // an interior instant
        tl.erase(tl.begin() + long(k), tl.begin() + long(k) + 2);
        m.what = "root dropped";
      }
      break;
    }
    case 4: {  // an integer changed by one
      std::vector<json::json_pointer> nums;
      collect(
          c, json::json_pointer(), [](const json& j) { return is_rational_text(j) || j.is_number_integer(); }, nums);
      const auto p = nums[pick(nums.size())];
      const int d = pick(2) ? 1 : -1;
      if (c[p].is_number_integer())
        c[p] = c[p].get<long long>() + d;
      else
        c[p] = plus_one(c[p].get<std::string>(), d);
      m.what = "integer changed by one at " + p.to_string();
      const std::string top = p.to_string().substr(0, p.to_string().find('/', 1));
      m.may_stay_valid = top == "/gap_points" ||
                         (top == "/continuous_touching" && p.to_string().find("gap_points") != std::string::npos) ||
                         p.to_string().find("/cell_sample") != std::string::npos ||
                         (top == "/timeline" &&
                          p.to_string().find("/instant/") != std::string::npos);  // a bracket may still prove its root
      break;
    }
    case 5:
      m.what = "scene swapped";
      m.scene_text = b.other_scene_text;
      break;
    case 6: {  // a key duplicated, in the text
      std::string t = c.dump();
      std::vector<std::size_t> at;
      for (std::size_t i = t.find("\":"); i != std::string::npos; i = t.find("\":", i + 1)) at.push_back(i);
      const std::size_t i = at[pick(at.size())];
      const std::size_t start = t.rfind('"', i - 1);
      const std::string key = t.substr(start, i + 2 - start);
      t.insert(start, key + "\"forged\",");
      m.what = "key duplicated: " + key;
      m.text = t;
      return m;
    }
    case 7: {  // a bracket widened past its neighbour
      if (!has_timeline) {
        c["answer"]["first_contact"] = json();
        m.what = "first contact dropped";
        break;
      }
      const std::size_t k = 2 * pick(tl.size() / 2 + 1);
      json& in = tl[k]["instant"];
      if (k + 1 < tl.size() && (k == 0 || pick(2))) {
        mpq_class next(tl[k + 2]["instant"]["lo"].get<std::string>());
        next.canonicalize();
        in["hi"] = mpq_class(next + mpq_class(1, 1 << 30)).get_str();
      } else {
        mpq_class prev(tl[k - 2]["instant"]["hi"].get<std::string>());
        prev.canonicalize();
        in["lo"] = mpq_class(prev - mpq_class(1, 1 << 30)).get_str();
      }
      m.what = "bracket " + std::to_string(k / 2) + " widened past its neighbour";
      break;
    }
    case 8: {  // a status flipped
      std::vector<json::json_pointer> st;
      collect(
          c, json::json_pointer(),
          [](const json& j) { return j.is_object() && j.contains("status") && j["status"].is_string(); }, st);
      const auto p = st[pick(st.size())];
      const std::string old = c[p]["status"];
      const std::string others[] = {"separate", "touching", "overlapping"};
      std::string now = old;
      while (now == old) now = others[pick(3)];
      c[p]["status"] = now;
      m.what = "status flipped at " + p.to_string();
      break;
    }
    case 9: {  // an evidence sign flipped
      std::vector<json::json_pointer> ev;
      collect(
          c, json::json_pointer(),
          [](const json& j) { return j.is_object() && j.contains("sign") && j.contains("poly"); }, ev);
      if (ev.empty()) {
        c["answer"]["collides"] = !c["answer"]["collides"].get<bool>();
        m.what = "collides flipped";
        break;
      }
      const auto p = ev[pick(ev.size())];
      const std::string old = c[p]["sign"];
      c[p]["sign"] = old == "positive" ? "negative" : "positive";
      m.what = "evidence sign flipped at " + p.to_string();
      break;
    }
    default: {  // a gap point dropped
      json& gp = has_timeline ? c["gap_points"] : c["continuous_touching"]["gap_points"];
      if (gp.empty()) {
        c["answer"]["intervals"] = json::array();
        m.what = "intervals emptied";
        break;
      }
      gp.erase(gp.begin() + long(pick(gp.size())));
      m.what = "gap point dropped";
      m.may_stay_valid = true;  // the next piece may still be root-free
      break;
    }
  }
  m.text = c.dump();
  if (c["answer"] != b.cert["answer"] || m.scene_text != b.scene_text) m.may_stay_valid = false;
  return m;
}

bool independent_valid(const Base& b, const Mutant& m) {
  return check::check_certificate_text(m.scene_text, b.scene_path, m.text, "mutant").outcome == check::Outcome::valid;
}
bool prover_algebra_valid(const Base& b, const Mutant& m) {
  std::string structure;
  json cert;
  try {
    cert = parse_json_document(m.text, "mutant", &structure);
  } catch (const SceneError&) {
    return false;
  }
  if (!structure.empty()) return false;
  try {
    if (m.scene_text == b.scene_text) return prover_self_check(b.scene, b.doc, cert).valid;
    const Scene other = parse_scene(m.scene_text, "other");
    return prover_self_check(other, parse_json_document(m.scene_text, "other"), cert).valid;
  } catch (const std::exception&) {
    return false;
  }
}

void campaign(std::size_t per_kind) {
  std::uint64_t seed = std::random_device{}();
  if (const char* s = std::getenv("ECCD_MUTATION_SEED")) seed = std::strtoull(s, nullptr, 10);
  std::cout << "mutation campaign: seed " << seed << " (ECCD_MUTATION_SEED=" << seed << " repeats it), " << per_kind
            << " mutations per kind\n";
  std::mt19937_64 rng(seed);
  const std::vector<Base> kinds = {
      base("eccd-certificate/2 2D", "paper003/example2-away-1e-3.json", "paper003/example2.json"),
      base("eccd-certificate/2 3D", "touch3d/touch-and-separate.json", "touch3d/touch-then-overlap.json"),
      base("eccd-certificate/2 2D continuous", "rolling/circles-rolling.json", "paper003/example2.json")};
  for (const Base& b : kinds) {
    INFO(b.name << " (seed " << seed << ")");
    REQUIRE(independent_valid(b, Mutant{"none", b.cert.dump(), b.scene_text, true}));
    REQUIRE(prover_algebra_valid(b, Mutant{"none", b.cert.dump(), b.scene_text, true}));
    std::size_t rejected = 0, neutral_valid = 0;
    for (std::size_t i = 0; i < per_kind; ++i) {
      const Mutant m = mutate(b, rng);
      const bool v1 = independent_valid(b, m), v2 = prover_algebra_valid(b, m);
      INFO("mutation " << i << ": " << m.what);
      if (!m.may_stay_valid) {
        CHECK_FALSE(v1);
        CHECK_FALSE(v2);
      }
      if (!v1 && !v2)
        ++rejected;
      else
        ++neutral_valid;
    }
    std::cout << "  " << b.name << ": " << per_kind << " mutations, " << rejected << " rejected by both checkers, "
              << neutral_valid << " valid in one or both with the answer and scene unchanged\n";
  }
}

}  // namespace

TEST_CASE("Mutation campaign: no answer-changing mutation of an eccd-certificate/2 is VALID in either checker",
          "[mutation][certificate]") {
  campaign(500);
}

TEST_CASE("Mutation campaign, long: 10^5 mutations per kind", "[.long][mutation-long]") { campaign(100000); }

}  // namespace ECCD_UNITY_ID
