#pragma once
// Scene reader: reads and validates a scene file into a Scene (kernel/scene.hpp).
//
// Statement. Implements ../shared/spec/scene-format.md, format
// "ellipse-ccd-scene/1": exact numbers, polynomials in t (power or Bernstein
// form), shapes (semi_axes, semi_axes_squared, matrix), motions (static,
// matrix, kinematic, euler, cycloidal) and the optional stored answer.
// Every check a scene can fail raises SceneError with the message
//     FILE: PLACE: what is wrong
// where PLACE is the JSON pointer of the offending value (e.g. /a/motion/d/2),
// "top level" for the whole document, or "line L, column C" for malformed
// JSON. No other exception escapes read_scene_file / parse_scene (apart from
// std::bad_alloc). Requirements: GMP rationals (number/rational_traits.hpp),
// nlohmann json 3.11. All decisions (positivity, symmetry, conic type,
// vanishing of w(t), det, E(t), ...) are exact: rationals and Sturm counts.
//
// Choices where the spec leaves room (what a user would expect):
//  1. Number strings: an optional sign then an integer ("-63", "+5", "007"),
//     a fraction of integers ("-3/7"; denominator digits only, non-zero;
//     "6/4" is read as 3/2), or a decimal with optional exponent ("1.8",
//     "2.5e-3", "-.5", "5.", "1E3"), read as its exact decimal value.
//     Rejected: whitespace anywhere, hex, "inf"/"nan", "1.5/2", "1/-2", a
//     decimal without digits ("." / "e5"), |exponent| > 10000.
//  2. JSON integers of any size are exact (the reader keeps the raw digits of
//     integers beyond 64 bits; only integers beyond the double range are
//     refused by the JSON parser as "number overflow"). A JSON number with a
//     fraction part or exponent (1.8, 1e3, 2.0) is always rejected.
//  3. "dim" is any exact number equal to 2 or 3 (2 or "2").
//  4. "name" must be a non-empty string; "note" a string; "answer": null is
//     the same as no answer.
//  5. Each of "a" and "b" needs both "shape" and "motion" (no default motion).
//  6. A duplicate key in any object is an error (JSON parsers silently keep
//     one of the values). Nesting deeper than 64 levels is an error.
//  7. Unknown keys are reported at the pointer of the key itself, with the
//     allowed keys listed; the "format" key is checked before everything else.
//  8. A polynomial may also be a bare JSON integer (a constant). A coefficient
//     array ["0"] is the zero polynomial; an empty array is an error.
//  9. A "matrix" shape is kept as given (not normalised). A "matrix" motion's
//     last-row entries must be the zero polynomial (after dropping zero
//     coefficients: ["0", "0"] is fine).
// 10. Where a polynomial vanishes on [0, 1], the message gives the root
//     exactly ("at t = 1/3") when it is rational with denominator < 2^15,
//     otherwise a rational bracket of width 2^-30 ("at t in [lo, hi]").
// 11. Answer: "collides" is required; "intervals", "contacts" and
//     "contact_intervals" (continuous touching, docs/answer-format.md) default
//     to [], "first_contact" to null. In an instant, "approx" is a required
//     string (not parsed); "lo"/"hi" may be missing (= null) but must be
//     both null or both numbers, with lo <= hi. collides = false requires
//     empty intervals/contacts and a null first_contact; collides = true
//     with an explicitly empty "intervals" is an error.
// 12. answer_to_json writes the four spec keys always, contact_intervals and
//     the extras (contact_points, undecided) only when non-empty;
//     answer_from_json rejects the extras (they are not part of a stored
//     answer).
// 13. Scene::path is set to the file label (the path for read_scene_file).
//     An unreadable file gives "FILE: cannot read the file: reason".
// 14. Input limits (InputLimits below, changed by the command line's
//     --max-file-bytes, --max-digits, --max-degree): a scene file of more than
//     max_file_bytes is refused before it is read whole (so /dev/zero ends at
//     once); a number whose exact value p/q has more than max_digits decimal
//     digits in p or q (or whose text is longer than 100 * max_digits
//     characters) is refused at its place; so is a polynomial of degree above
//     max_degree. The messages say "beyond the input limit" and name the
//     option. A NUL byte in the file is reported as such (a binary file), an
//     empty file as empty. Long keys and values are cut in messages (80
//     characters and "...").
// 15. "parameters" (scene-format.md, "Independent motions"): the
//     string "shared" (the default) or "independent", nothing else (Scene::
//     independent). The answer of an independent scene has exactly the keys
//     collides, s_intervals, t_intervals (each list [] when missing; collides
//     = false requires both empty, collides = true with an explicitly empty
//     list is an error, as for intervals); intervals, first_contact,
//     contacts, contact_intervals there are errors naming the key, and so
//     are s_intervals / t_intervals in a shared scene's answer.
//     answer_from_json (an answer file, no scene) takes an answer with
//     s_intervals or t_intervals as an independent one.
#include "number/rational_traits.hpp"
#include "kernel/answer.hpp"
#include "io/scene_error.hpp"
#include "kernel/scene.hpp"

#include <nlohmann/json.hpp>

#include <stdexcept>
#include <string>
#include <unordered_map>

namespace eccd {

// Limits on what a scene may ask for (choice 14). Defaults: 8 MiB files,
// 1000 digits per numerator / denominator, motion polynomials of degree 32.
struct InputLimits {
  std::size_t max_file_bytes = std::size_t(8) << 20;
  std::size_t max_digits = 1000;
  int max_degree = 32;
};
// The process-wide limits (read by every scene reader call).
InputLimits& input_limits();

// Reads and validates a scene; throws SceneError "FILE: PLACE: what is wrong".
Scene read_scene_file(const std::string& path);
Scene parse_scene(const std::string& json_text, const std::string& file_label);
// The bytes of a file, read once and at most max_file_bytes of them (a
// directory, an unreadable or too large file throws SceneError "FILE: ...").
// Opened without blocking and read only if it is a regular file: a FIFO, a
// device or a socket throws SceneError saying what it is; "/dev/stdin" (what a
// command's `-` reads) is the one stream read, blocking. Callers that need both the
// Scene and its JSON (certify, check-certificate) parse these same bytes twice
// instead of opening the file twice.
std::string read_file_bytes(const std::string& path);
// The same with another bound: larger than `limit` bytes throws SceneError
// "PATH: larger than LIMIT_TEXT of N bytes (OPTION)" (the files a command
// writes for itself and reads back, e.g. report's parts and worker files).
std::string read_bounded_file(const std::string& path, std::size_t limit, const std::string& limit_text,
                              const std::string& option = "");
// A JSON document read with the checks of choice 6 (duplicate keys, nesting
// depth); throws SceneError "LABEL: line L, column C: malformed JSON: ..." for a
// syntax error. A duplicate key or over-deep nesting throws SceneError too,
// unless structure_error is given: then it receives "PLACE: what" and the
// result is null (the certificate checker rejects such a certificate).
nlohmann::json parse_json_document(const std::string& json_text, const std::string& file_label,
                                   std::string* structure_error = nullptr);

// For readers of formats built on this one (io/animation_reader.hpp): the same
// strict JSON (choice 6, the file size limit of choice 14), numbers (choices 1,
// 2) and shapes, with the same messages "FILE: PLACE: what is wrong".
struct StrictJson {
  nlohmann::json root;
  std::unordered_map<std::string, std::string> raw_numbers;  // JSON pointer -> raw text of a non-integer number
};
StrictJson parse_strict_json(const std::string& json_text, const std::string& file_label);
Rational json_rational(const StrictJson& doc, const nlohmann::json& j, const std::string& file_label,
                       const std::string& place);
// A shape of dimension dim: the matrix Q (throws SceneError at `place`).
std::vector<std::vector<Rational>> json_shape(const StrictJson& doc, const nlohmann::json& j,
                                              const std::string& file_label, const std::string& place, int dim);
std::string json_place(const std::string& pointer);   // "top level" for "", long tokens cut
std::string json_quote(const std::string& text);      // a user's string in a message: quoted, cut at 80 characters
std::string json_type_name(const nlohmann::json& j);  // "an integer", "a number with a fraction part", ...

// Exact value of a number string (choice 1 above). Throws std::invalid_argument
// whose what() is the reason (the reader turns it into a SceneError).
Rational parse_rational(const std::string& text);

// An answer in the spec's format; instants {"approx", "lo", "hi"} with lo/hi
// "p/q" strings, or null when not certified (choice 12 for the extras).
nlohmann::json answer_to_json(const Answer& answer);
// One instant {"approx", "lo", "hi"} as answer_to_json writes it.
nlohmann::json instant_to_json(const Instant& instant);
// The stored "answer" of a scene at JSON pointer `place` of file `file_label`;
// throws SceneError.
Answer answer_from_json(const nlohmann::json& j, const std::string& file_label, const std::string& place);
// One instant as instant_to_json writes it (the same checks as in an answer); throws SceneError.
Instant instant_from_json(const nlohmann::json& j, const std::string& file_label, const std::string& place);

}  // namespace eccd
