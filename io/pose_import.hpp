#pragma once
// Keyframes -> an animation file (docs/animation-format.md, format
// ellipse-ccd-animation/1): the one conversion behind `eccd import-poses`
// (a CSV of poses and a shapes file, docs/import-poses.md) and the Python
// builder eccd.Animation.from_keyframes (arrays of positions and
// quaternions). Both fill Keyframes and write it with animation_json, so the
// same motion gives the same file whichever way it came in.
//
// Numbers. Every number is written by canonical_number from its exact value:
// an integer ("3"), a terminating decimal ("0.125", "-2.5e-30"), or a
// fraction "p/q" when the value has no finite decimal. A CSV field is read as
// the exact value of its text (io/scene_reader.hpp parse_rational: "0.1" is
// 1/10); a double from a program is read as its shortest round-trip decimal
// (number_from_double: what Python's repr prints, so 0.1 is 1/10 too, not the
// binary value 0.1000000000000000055...). A 2D angle θ (radians) becomes the
// orientation pair (w, z) = (cos θ/2, sin θ/2) computed in double and written
// by number_from_double: the rotation of that pair is then exact and within
// a few ulps of θ (the format needs no unit length).
//
// CSV (pose_keyframes_from_csv): one pose per line, fields separated by
// commas, spaces around a field ignored; 3D `time, body, x, y, z, qw, qx, qy,
// qz`, 2D `time, body, x, y, angle`; blank lines and lines starting with '#'
// are skipped, and so is a first line whose first field is "time" (a
// header). Lines may come in any order; the key times are the distinct times,
// increasing; every body of the shapes file needs exactly one pose per key
// time. Errors: SceneError "CSV: line L, column C (name): what is wrong", or
// "CSV: ..." for what no one line holds (a body without a pose at a time).
//
// Shapes file (the animation format without times and poses):
//   {"format": "eccd-shapes/1" (optional), "name": "id", "dim": 3,
//    "bodies": [{"name": "a", "group": "g" (optional), "shape": {...}}, ...],
//    "pairs": "all" | "between-groups" | [["a", "b"], ...] (optional),
//    "note": "..." (optional)}
// read with the scene reader's strict JSON; errors name the file and the
// JSON place. The bodies keep its order.
//
// The result of animation_json is checked by the animation reader
// (io/animation_reader.hpp) before it is returned: a zero quaternion, a
// singular deformation, two opposite orientations a half turn apart raise
// its SceneError, naming `label` and the JSON place (and the body and frame).
#include "number/rational_traits.hpp"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace eccd {

inline constexpr const char* kShapesFormat = "eccd-shapes/1";

// The exact value written canonically (see above).
std::string canonical_number(const Rational& q);
// A finite double by its shortest round-trip decimal, then canonical_number;
// std::invalid_argument for inf and NaN.
std::string number_from_double(double x);
// A number's text (parse_rational's forms) written canonically; std::invalid_argument with the reason otherwise.
std::string canonical_number_text(const std::string& text);
// 2D: the orientation pair (w, z) of the angle theta in radians (see above).
std::vector<std::string> orientation_of_angle(double theta);

struct KeyframePose {
  std::vector<std::string> position;                  // dim numbers
  std::vector<std::string> orientation;               // 3D [w, x, y, z], 2D [w, z]
  std::vector<std::vector<std::string>> deformation;  // dim x dim, or empty (the identity)
};
struct KeyframeBody {
  std::string name, group;          // group "" = none
  nlohmann::ordered_json shape;     // a shape of the scene format
  std::vector<KeyframePose> poses;  // one per key time
};
struct Keyframes {
  std::string name = "animation", note;
  int dim = 3;
  std::vector<std::string> times;  // canonical numbers, increasing
  std::vector<KeyframeBody> bodies;
  nlohmann::ordered_json pairs = "all";
};

// The animation file's JSON, checked by the animation reader under `label`.
nlohmann::ordered_json animation_json(const Keyframes& k, const std::string& label);
// animation_json's text as eccd import-poses writes it (one line per pose, a final newline).
std::string animation_text(const nlohmann::ordered_json& animation);

// The shapes file's bodies, name, dim, pairs and note (times and poses empty).
Keyframes shapes_from_text(const std::string& json_text, const std::string& label);
// The CSV's poses into `shapes` (from shapes_from_text): times and poses filled.
Keyframes pose_keyframes_from_csv(const std::string& csv_text, const std::string& csv_label, Keyframes shapes);

}  // namespace eccd
