// Answers in the spec's JSON format (io/scene_reader.hpp, choice 12):
// instants {"approx", "lo", "hi"} with lo and hi as "p/q" strings or null, the
// four spec keys always, contact_intervals, contact_points and undecided only
// when non-empty; an independent scene's answer as collides, s_intervals,
// t_intervals. The reading side is the scene reader's (answer_from_json).
#include "io/scene_reader.hpp"

namespace eccd {

using json = nlohmann::json;

json instant_to_json(const Instant& in) {
  json o = json::object();
  o["approx"] = in.approx;
  o["lo"] = in.lo ? json(in.lo->get_str()) : json(nullptr);
  o["hi"] = in.hi ? json(in.hi->get_str()) : json(nullptr);
  return o;
}

namespace {

json interval_list_to_json(const std::vector<std::pair<Instant, Instant>>& v) {
  json a = json::array();
  for (const auto& [s, e] : v) a.push_back(json::array({instant_to_json(s), instant_to_json(e)}));
  return a;
}

}  // namespace

json answer_to_json(const Answer& answer) {
  json o = json::object();
  o["collides"] = answer.collides;
  if (answer.independent) {  // scene-format.md, "Independent motions": no intervals / first_contact / contacts
    o["s_intervals"] = interval_list_to_json(answer.s_intervals);
    o["t_intervals"] = interval_list_to_json(answer.t_intervals);
    if (!answer.undecided.empty()) {
      json u = json::array();
      for (const auto& c : answer.undecided) u.push_back(instant_to_json(c));
      o["undecided"] = u;
    }
    return o;
  }
  o["intervals"] = interval_list_to_json(answer.intervals);
  o["first_contact"] = answer.first_contact ? instant_to_json(*answer.first_contact) : json(nullptr);
  json contacts = json::array();
  for (const auto& c : answer.contacts) contacts.push_back(instant_to_json(c));
  o["contacts"] = contacts;
  if (!answer.contact_points.empty()) {
    json pts = json::array();
    for (const auto& p : answer.contact_points) pts.push_back(json(p.x));
    o["contact_points"] = pts;
  }
  if (!answer.contact_intervals.empty()) o["contact_intervals"] = interval_list_to_json(answer.contact_intervals);
  if (!answer.undecided.empty()) {
    json u = json::array();
    for (const auto& c : answer.undecided) u.push_back(instant_to_json(c));
    o["undecided"] = u;
  }
  return o;
}

}  // namespace eccd
