// Message text for the strict JSON readers (io/scene_reader.hpp, io/animation_reader.hpp):
// JSON pointers as places ("top level", long tokens cut), user strings
// quoted and cut, long digit runs shortened, the type of a JSON value in
// words, and the "line L, column C: malformed JSON: ..." text of a parser
// error. Every reader's "FILE: PLACE: what is wrong" is built from these, so
// that all formats speak alike. Requirements: nlohmann json 3.11.
#pragma once

#include <nlohmann/json.hpp>

#include <cstddef>
#include <string>
#include <vector>

namespace eccd::json_messages {

// A JSON pointer token with '~' and '/' escaped (RFC 6901).
std::string escape_token(const std::string& key);
// The pointer of a member / an element of the value at `ptr`.
std::string child(const std::string& ptr, const std::string& key);
std::string child(const std::string& ptr, std::size_t i);
// A JSON pointer for a message: "top level" for "", each token cut to 80 characters.
std::string place_text(const std::string& ptr);
// A message with each run of more than 40 digits shortened to its first 20
// and last 8 digits and the count (a 1000-digit number is not echoed whole).
std::string shorten_digits(const std::string& m);
// A user string in a message: JSON-quoted, shortened.
std::string quote(const std::string& s);
// "an integer", "a number with a fraction part", "an object", ...
std::string type_name(const nlohmann::json& j);
std::string join(const std::vector<std::string>& v, const char* sep = ", ");
// "line L, column C: malformed JSON: reason" for an error the JSON parser
// reported at byte `pos` of `text` (the parser's own line and column when its
// message has them).
std::string json_error_text(const std::string& text, std::size_t pos, const std::string& what);

}  // namespace eccd::json_messages
