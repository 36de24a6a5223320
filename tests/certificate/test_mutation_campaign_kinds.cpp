// The mutation campaign (docs/checking.md) for the kinds eccd-check covers
// beside eccd-certificate/2: eccd-bezier-certificate/2 (3D, the interval
// Bézier proof), eccd-independent-certificate/3 (independent motions: strips,
// ends with Krawczyk chains and exclusion trees; mutate_independent) and
// eccd-cycloidal-certificate/2 (2D cycloidal, MPFI; an
// incomplete certificate with an undecided stretch, so that issue 32's point
// 5 is exercised: collides is null there, never false). Genuine certificates
// are mutated at random (seed printed; ECCD_MUTATION_SEED repeats it) and
// given to eccd-check's library: collides flipped, an end moved, an interval
// or a root dropped or added, an integer changed by one, the scene swapped, a
// key duplicated, a bracket widened past its neighbour, a status (or a
// piece's kind) flipped, a gap point dropped or an exclusion tree's node
// flipped. No mutant that changes the answer, the scene, the net of F or
// duplicates a key may be VALID; a mutant may stay VALID only where the
// answer is unchanged and the mutated claim may still hold (a box, a gap
// point, a bracket end inside the timeline). [mutation]: 500 per kind per
// run; [.long][mutation-long]: 10^5 per kind (hidden, run by hand).
#include "certificate/check/verdict.hpp"
#include "certificate/write/bezier_certificate.hpp"
#include "certificate/write/cycloidal_certificate.hpp"
#include "certificate/write/independent_certificate.hpp"
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

// 2D: B static, A (a unit circle) passing at distance 2 at t = 1/2: a touch no enclosure decides (an undecided stretch)
const char* kCycloidalTouch = R"({"format": "ellipse-ccd-scene/1", "name": "cyc-touch", "dim": 2,
    "a": {"shape": {"semi_axes": ["1", "1"]}, "motion": {"type": "cycloidal", "angle_over_pi": ["0", "1"], "translation": [["-2", "4"], ["2", "0"]]}},
    "b": {"shape": {"semi_axes": ["1", "1"]}, "motion": {"type": "static"}}})";
// the same crossing B: a collision, proved
const char* kCycloidalCross = R"({"format": "ellipse-ccd-scene/1", "name": "cyc-cross", "dim": 2,
    "a": {"shape": {"semi_axes": ["1", "1"]}, "motion": {"type": "cycloidal", "angle_over_pi": ["0", "1"], "translation": [["-2", "4"], ["1", "0"]]}},
    "b": {"shape": {"semi_axes": ["1", "1"]}, "motion": {"type": "static"}}})";

struct Base {
  std::string name, scene_text, other_scene_text;
  json cert;
  bool bezier = false, independent = false;
};

Base bezier_base(const std::string& rel, const std::string& other_rel) {
  Base b;
  b.name = "eccd-bezier-certificate/2 (" + rel + ")";
  b.bezier = true;
  b.scene_text = read_file_bytes(src + "/cases/" + rel);
  b.other_scene_text = read_file_bytes(src + "/cases/" + other_rel);
  const Scene s = parse_scene(b.scene_text, rel);
  b.cert = make_bezier_certificate(s, parse_json_document(b.scene_text, rel));
  return b;
}

Base independent_base(const std::string& rel, const std::string& other_rel) {
  Base b;
  b.name = "eccd-independent-certificate/3 (" + rel + ")";
  b.independent = true;
  b.scene_text = read_file_bytes(src + "/cases/" + rel);
  b.other_scene_text = read_file_bytes(src + "/cases/" + other_rel);
  const Scene s = parse_scene(b.scene_text, rel);
  b.cert = make_independent_certificate(s, parse_json_document(b.scene_text, rel));
  return b;
}

Base cycloidal_base(const std::string& text, const std::string& other_text) {
  Base b;
  b.name = "eccd-cycloidal-certificate/2 (an undecided touch)";
  b.scene_text = text;
  b.other_scene_text = other_text;
  const Scene s = parse_scene(text, "cyc");
  b.cert = make_cycloidal_certificate(s, parse_json_document(text, "cyc"));
  return b;
}

using eccd::test::collect;

using eccd::test::is_rational_text;

mpq_class rq(const json& j) {
  mpq_class q(j.get<std::string>());
  q.canonicalize();
  return q;
}

using eccd::test::Mutant;

// Where a changed number may leave a true claim (the answer unchanged): boxes, gap points, timeline brackets, samples.
bool harmless_place(const std::string& p) {
  return p.find("/boxes/") != std::string::npos || p.rfind("/gap_points", 0) == 0 ||
         p.find("/cell_sample") != std::string::npos ||
         (p.rfind("/timeline", 0) == 0 && p.find("/instant/") != std::string::npos) ||
         p.find("/epsilon") != std::string::npos || p == "/precision_bits" || p == "/delta/precision_bits";
}

Mutant mutate(const Base& b, std::mt19937_64& rng) {
  auto pick = [&](std::size_t n) { return std::size_t(std::uniform_int_distribution<std::size_t>(0, n - 1)(rng)); };
  json c = b.cert;
  Mutant m;
  m.scene_text = b.scene_text;
  json& seq = b.bezier ? c["pieces"] : c["timeline"];
  switch (pick(11)) {
    case 0: {
      json& col = c["answer"]["collides"];
      col = col.is_null() ? json(false) : json(!col.get<bool>());
      m.what = "collides flipped";
      break;
    }
    case 1: {  // an end moved
      std::vector<json::json_pointer> ends;
      collect(
          c, json::json_pointer(),
          [](const json& j) { return j.is_object() && j.contains("lo") && j.contains("hi") && j["lo"].is_string(); },
          ends);
      const auto p = ends[pick(ends.size())];
      json& in = c[p];
      const char* key = pick(2) ? "lo" : "hi";
      const mpq_class lo = rq(in["lo"]), hi = rq(in["hi"]);
      mpq_class w = hi - lo;
      if (w == 0) w = mpq_class(1, 1 << 20);
      const mpq_class shift[] = {w / 2, -w / 2, w * 2, -w * 2, mpq_class(1, 1000), mpq_class(-1, 1000)};
      in[key] = mpq_class((key[0] == 'l' ? lo : hi) + shift[pick(6)]).get_str();
      m.what = std::string("end moved: ") + p.to_string() + "/" + key;
      m.may_stay_valid = p.to_string().rfind("/timeline", 0) == 0;
      break;
    }
    case 2: {
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
    case 3: {  // a root dropped or added: an end piece, or an instant and its cell
      if (b.bezier) {
        std::vector<std::size_t> ends;
        for (std::size_t k = 0; k < seq.size(); ++k)
          if (seq[k]["kind"] == "end") ends.push_back(k);
        if (ends.empty() || pick(2)) {
          const std::size_t k = pick(seq.size());
          seq.insert(seq.begin() + long(k), seq[k]);
          m.what = "piece duplicated";
        } else {
          seq.erase(seq.begin() + long(ends[pick(ends.size())]));
          m.what = "end dropped";
        }
      } else if (seq.size() < 5 || pick(2)) {
        const std::size_t k = 1 + 2 * pick(seq.size() / 2);
        json cell = seq[k], inst = seq[k - 1];
        seq.insert(seq.begin() + long(k), cell);
        seq.insert(seq.begin() + long(k) + 1, inst);
        m.what = "root added";
      } else {
        const std::size_t k = 2 + 2 * pick((seq.size() - 3) / 2);
        seq.erase(seq.begin() + long(k), seq.begin() + long(k) + 2);
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
      else {
        const std::string s = c[p].get<std::string>();
        const std::size_t slash = s.find('/');
        mpz_class n(slash == std::string::npos ? s : s.substr(0, slash), 10);
        n += d;
        c[p] = n.get_str() + (slash == std::string::npos ? "" : s.substr(slash));
      }
      m.what = "integer changed by one at " + p.to_string();
      m.may_stay_valid = harmless_place(p.to_string());
      break;
    }
    case 5:
      m.what = "scene swapped";
      m.scene_text = b.other_scene_text;
      break;
    case 6: {
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
      if (b.bezier) {
        const std::size_t k = pick(seq.size());
        if (k + 1 < seq.size())
          seq[k]["hi"] = mpq_class(rq(seq[k + 1]["hi"]) + mpq_class(1, 1 << 30)).get_str();
        else
          seq[k]["lo"] = mpq_class(rq(seq[k - 1]["lo"]) - mpq_class(1, 1 << 30)).get_str();
        m.what = "piece " + std::to_string(k) + " widened past its neighbour";
      } else {
        const std::size_t k = 2 * pick(seq.size() / 2 + 1);
        json& in = seq[k]["instant"];
        if (k + 1 < seq.size() && (k == 0 || pick(2)))
          in["hi"] = mpq_class(rq(seq[k + 2]["instant"]["lo"]) + mpq_class(1, 1 << 30)).get_str();
        else
          in["lo"] = mpq_class(rq(seq[k - 2]["instant"]["hi"]) - mpq_class(1, 1 << 30)).get_str();
        m.what = "bracket " + std::to_string(k / 2) + " widened past its neighbour";
      }
      break;
    }
    case 8: {  // a status (a piece's kind) flipped
      if (b.bezier) {
        const std::size_t k = pick(seq.size());
        const std::string old = seq[k]["kind"];
        seq[k]["kind"] = old == "in" ? "out" : old == "out" ? "in" : (pick(2) ? "in" : "out");
        m.what = "piece " + std::to_string(k) + " kind flipped";
      } else {
        const std::size_t k = pick(seq.size());
        const std::string old = seq[k]["status"];
        const std::string others[] = {"separate", "touching", "overlapping", "uncertain"};
        std::string now = old;
        while (now == old) now = others[pick(4)];
        seq[k]["status"] = now;
        m.what = "status flipped at " + std::to_string(k);
      }
      break;
    }
    case 9: {  // the net (Bézier) or the precision changed: F's claim must fail, or a proof
      if (b.bezier) {
        json& co = c["net"]["coefficients"];
        json& x = co[pick(co.size())][pick(co[0].size())];
        x = mpq_class(rq(x) * 2 + 1).get_str();
        m.what = "net coefficient changed";
      } else {
        json& gp = c["gap_proofs"];
        if (gp.empty()) {
          c["complete"] = !c["complete"].get<bool>();
          m.what = "complete flipped";
          break;
        }
        json& x = gp[pick(gp.size())];
        x = x == "natural" ? "monotone" : "natural";
        m.what = "gap proof renamed";
        m.may_stay_valid = true;  // another proof may hold on the same piece
      }
      break;
    }
    default: {  // a gap point dropped, or an exclusion tree node flipped
      if (b.bezier) {
        std::vector<std::size_t> ends;
        for (std::size_t k = 0; k < seq.size(); ++k)
          if (seq[k]["kind"] == "end") ends.push_back(k);
        if (ends.empty()) {
          c["answer"]["contacts"].push_back({{"approx", "0.5"}, {"lo", "1/2"}, {"hi", "1/2"}});
          m.what = "contact added";
          break;
        }
        json& e = seq[ends[pick(ends.size())]]["exclusion"];
        std::string t = e.get<std::string>();
        const std::size_t i = pick(t.size());
        t[i] = t[i] == '0' ? '1' : '0';
        e = t;
        m.what = "exclusion node flipped";
        m.may_stay_valid = true;  // a finer tree may still exclude
      } else {
        json& gp = c["gap_points"];
        if (gp.empty()) {
          c["answer"]["intervals"] = json::array();
          m.what = "intervals emptied";
          break;
        }
        const std::size_t i = pick(gp.size());
        gp.erase(gp.begin() + long(i));
        c["gap_proofs"].erase(c["gap_proofs"].begin() + long(i));
        m.what = "gap point dropped";
        m.may_stay_valid = true;
      }
      break;
    }
  }
  m.text = c.dump();
  if (c["answer"] != b.cert["answer"] || m.scene_text != b.scene_text ||
      c.value("net", json()) != b.cert.value("net", json()) || c["format"] != b.cert["format"])
    m.may_stay_valid = false;
  return m;
}

// Mutations 9 and 10 of an independent-motion certificate: the net or the reduction, an end's tree or system.
void mutate_independent_proof(json& c, json& seq, json& ans, const char* list, Mutant& m, std::mt19937_64& rng,
                              int which) {
  auto pick = [&](std::size_t n) { return std::size_t(std::uniform_int_distribution<std::size_t>(0, n - 1)(rng)); };
  switch (which) {
    case 4: {  // an integer changed by one
      std::vector<json::json_pointer> nums;
      collect(
          c, json::json_pointer(), [](const json& j) { return is_rational_text(j) || j.is_number_integer(); }, nums);
      const auto p = nums[pick(nums.size())];
      const int d = pick(2) ? 1 : -1;
      if (c[p].is_number_integer())
        c[p] = c[p].get<long long>() + d;
      else {
        const std::string t = c[p].get<std::string>();
        const std::size_t slash = t.find('/');
        mpz_class n(slash == std::string::npos ? t : t.substr(0, slash), 10);
        n += d;
        c[p] = n.get_str() + (slash == std::string::npos ? "" : t.substr(slash));
      }
      m.what = "integer changed by one at " + p.to_string();
      m.may_stay_valid = p.to_string().find("/boxes/") != std::string::npos ||
                         p.to_string().find("/chain/") != std::string::npos || p.to_string() == "/precision_bits";
      break;
    }
    case 9: {  // the net, or the bodies held still
      if (pick(4) == 0) {
        json& r = c["reduced"];
        if (r.empty())
          r.push_back(pick(2) ? "s" : "t");
        else
          r.erase(r.begin());
        m.what = "reduced changed";
      } else {
        json& co = c["net"]["coefficients"];
        json& x = co[pick(co.size())];
        x = mpq_class(rq(x) * 2 + 1).get_str();
        m.what = "net coefficient changed";
      }
      break;
    }
    default: {  // an exclusion tree's node flipped, or an end's system renamed
      std::vector<std::size_t> ends;
      for (std::size_t k = 0; k < seq.size(); ++k)
        if (seq[k]["kind"] == "end") ends.push_back(k);
      if (ends.empty()) {
        ans[list] = json::array();
        m.what = std::string(list) + " emptied";
        break;
      }
      json& e = seq[ends[pick(ends.size())]];
      if (pick(3) == 0) {
        const std::string names[] = {"fold", "0", "1", "free"};
        std::string now = e["system"];
        while (now == e["system"]) now = names[pick(4)];
        e["system"] = now;
        m.what = "end system renamed";
        break;
      }
      std::string t = e["exclusion"].get<std::string>();
      const std::size_t i = pick(t.size());
      t[i] = t[i] == '0' ? '1' : '0';
      e["exclusion"] = t;
      m.what = "exclusion node flipped";
      m.may_stay_valid = true;  // a finer tree may still exclude
      break;
    }
  }
}

// The same mutations on an independent-motion certificate: its items (s_proof, t_proof) take the pieces' place.
Mutant mutate_independent(const Base& b, std::mt19937_64& rng) {
  auto pick = [&](std::size_t n) { return std::size_t(std::uniform_int_distribution<std::size_t>(0, n - 1)(rng)); };
  json c = b.cert;
  Mutant m;
  m.scene_text = b.scene_text;
  const char* proof = pick(2) ? "s_proof" : "t_proof";
  json& seq = c[proof];
  json& ans = c["answer"];
  const char* list = pick(2) ? "s_intervals" : "t_intervals";
  const std::size_t which = pick(11);
  switch (which) {
    case 0:
      ans["collides"] = pick(3) == 0 ? json(nullptr) : json(!ans["collides"].get<bool>());
      m.what = "collides flipped";
      break;
    case 1: {  // an end moved: an item's, an answer instant's or a bracket's
      std::vector<json::json_pointer> ends;
      collect(
          c, json::json_pointer(),
          [](const json& j) { return j.is_object() && j.contains("lo") && j.contains("hi") && j["lo"].is_string(); },
          ends);
      const auto p = ends[pick(ends.size())];
      json& in = c[p];
      const char* key = pick(2) ? "lo" : "hi";
      const mpq_class lo = rq(in["lo"]), hi = rq(in["hi"]);
      const mpq_class w = hi > lo ? mpq_class(hi - lo) : mpq_class(1, 1 << 20);
      const mpq_class shift[] = {w / 2, -w / 2, w * 2, -w * 2, mpq_class(1, 1000), mpq_class(-1, 1000)};
      in[key] = mpq_class((key[0] == 'l' ? lo : hi) + shift[pick(6)]).get_str();
      m.what = std::string("end moved: ") + p.to_string() + "/" + key;
      break;
    }
    case 2: {
      json& iv = ans[list];
      if (!iv.empty() && pick(2)) {
        iv.erase(iv.begin() + long(pick(iv.size())));
        m.what = std::string(list) + ": interval dropped";
      } else {
        iv.push_back(
            json::array({{{"approx", "1"}, {"lo", "1"}, {"hi", "1"}}, {{"approx", "1"}, {"lo", "1"}, {"hi", "1"}}}));
        m.what = std::string(list) + ": interval added";
      }
      break;
    }
    case 3: {  // an item duplicated or an end dropped
      std::vector<std::size_t> ends;
      for (std::size_t k = 0; k < seq.size(); ++k)
        if (seq[k]["kind"] == "end") ends.push_back(k);
      if (ends.empty() || pick(2)) {
        const std::size_t k = pick(seq.size());
        seq.insert(seq.begin() + long(k), seq[k]);
        m.what = std::string(proof) + ": item duplicated";
      } else {
        seq.erase(seq.begin() + long(ends[pick(ends.size())]));
        m.what = std::string(proof) + ": end dropped";
      }
      break;
    }
    case 4:
      mutate_independent_proof(c, seq, ans, list, m, rng, 4);
      break;
    case 5:
      m.what = "scene swapped";
      m.scene_text = b.other_scene_text;
      break;
    case 6: {
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
    case 7: {  // an item widened past its neighbour
      const std::size_t k = pick(seq.size());
      if (k + 1 < seq.size())
        seq[k]["hi"] = mpq_class(rq(seq[k + 1]["hi"]) + mpq_class(1, 1 << 30)).get_str();
      else if (k > 0)
        seq[k]["lo"] = mpq_class(rq(seq[k - 1]["lo"]) - mpq_class(1, 1 << 30)).get_str();
      else
        seq[k]["hi"] = "2";
      m.what = std::string(proof) + " item " + std::to_string(k) + " widened past its neighbour";
      break;
    }
    case 8: {  // an item's kind flipped
      const std::size_t k = pick(seq.size());
      const std::string old = seq[k]["kind"];
      seq[k]["kind"] = old == "in" ? "out" : old == "out" ? "in" : (pick(2) ? "in" : "out");
      m.what = std::string(proof) + " item " + std::to_string(k) + " kind flipped";
      break;
    }
    default:
      mutate_independent_proof(c, seq, ans, list, m, rng, int(which));
      break;
  }
  m.text = c.dump();
  if (c["answer"] != b.cert["answer"] || m.scene_text != b.scene_text || c["net"] != b.cert["net"] ||
      c["reduced"] != b.cert["reduced"])
    m.may_stay_valid = false;
  return m;
}

bool valid(const Mutant& m) {
  return check::check_certificate_text(m.scene_text, "scene", m.text, "mutant").outcome == check::Outcome::valid;
}

void campaign(std::size_t per_kind) {
  std::uint64_t seed = std::random_device{}();
  if (const char* s = std::getenv("ECCD_MUTATION_SEED")) seed = std::strtoull(s, nullptr, 10);
  std::cout << "mutation campaign (Bezier, independent, cycloidal): seed " << seed << " (ECCD_MUTATION_SEED=" << seed
            << " repeats it), " << per_kind << " mutations per kind\n";
  std::mt19937_64 rng(seed);
  const std::vector<Base> kinds = {bezier_base("spheres/spheres-crossing.json", "paper002/example.json"),
                                   independent_base("independent/discs-end.json", "independent/disc-turning.json"),
                                   cycloidal_base(kCycloidalTouch, kCycloidalCross)};
  for (const Base& b : kinds) {
    INFO(b.name << " (seed " << seed << ")");
    REQUIRE(valid(Mutant{"none", b.cert.dump(), b.scene_text, true}));
    if (!b.bezier && !b.independent) {
      REQUIRE(b.cert["complete"] == false);
      REQUIRE(b.cert["answer"]["collides"].is_null());
    }
    std::size_t rejected = 0, neutral_valid = 0;
    for (std::size_t i = 0; i < per_kind; ++i) {
      const Mutant m = b.independent ? mutate_independent(b, rng) : mutate(b, rng);
      const bool v = valid(m);
      INFO("mutation " << i << ": " << m.what);
      if (!m.may_stay_valid) CHECK_FALSE(v);
      if (!v)
        ++rejected;
      else
        ++neutral_valid;
    }
    std::cout << "  " << b.name << ": " << per_kind << " mutations, " << rejected << " rejected, " << neutral_valid
              << " valid with the answer, scene and net unchanged\n";
  }
}

}  // namespace

TEST_CASE("Mutation campaign: no answer-changing mutation of a Bezier, independent or cycloidal certificate is VALID",
          "[mutation][certificate]") {
  campaign(500);
}

TEST_CASE("Mutation campaign, Bezier, independent and cycloidal, long: 10^5 mutations per kind",
          "[.long][mutation-long]") {
  campaign(100000);
}

}  // namespace ECCD_UNITY_ID
