#include "compare/external_answers.hpp"

#include "api/judge.hpp"
#include "io/scene_error.hpp"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace fs = std::filesystem;

namespace eccd {

ExternalEngine parse_external(const std::string& spec) {
  const auto eq = spec.find('=');
  if (eq == std::string::npos || eq == 0 || eq + 1 == spec.size())
    throw std::invalid_argument("--external " + spec +
                                ": expected NAME=DIR (a name for the engine, then the folder of its answer files)");
  ExternalEngine e{spec.substr(0, eq), spec.substr(eq + 1)};
  if (e.name.size() > 40) throw std::invalid_argument("--external " + spec + ": the name is longer than 40 characters");
  for (char c : e.name)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.'))
      throw std::invalid_argument(
          "--external " + spec + ": the name '" + e.name +
          "' may hold only letters, digits, '_', '-' and '.' (it becomes the pipeline label ext:NAME)");
  std::error_code ec;
  if (!fs::is_directory(e.dir, ec))
    throw std::invalid_argument("--external " + spec + ": " + e.dir + " is not a folder");
  return e;
}

std::optional<ExternalAnswer> read_external_answer(const ExternalEngine& engine, const std::string& scene_name) {
  if (scene_name.empty() || scene_name.find('/') != std::string::npos)
    return std::nullopt;  // no file can bear that name
  const fs::path p = fs::path(engine.dir) / (scene_name + ".json");
  std::error_code ec;
  if (!fs::is_regular_file(p, ec)) return std::nullopt;
  ExternalAnswer out;
  out.path = p.string();
  std::ifstream f(p, std::ios::binary);
  std::stringstream text;
  text << f.rdbuf();
  if (!f) {
    out.error = out.path + ": cannot be read";
    return out;
  }
  // The engine's own time, when the file gives one: taken out before the answer is read (the answer reader
  // knows only the answer's keys). Malformed JSON goes to the reader as it is, for its message.
  std::string answer_text = text.str();
  auto j = nlohmann::json::parse(answer_text, nullptr, false);
  if (j.is_object() &&
      (j.contains("time_us") || j.contains("time_ms"))) {  // else the text goes as it is (duplicate keys and all)
    for (const char* key : {"time_us", "time_ms"}) {
      if (!j.contains(key)) continue;
      if (!j[key].is_number() || j[key].get<double>() < 0) {
        out.error = out.path + ": /" + key + ": expected a non-negative number (the engine's time for the query)";
        return out;
      }
      if (out.time_us < 0) out.time_us = j[key].get<double>() * (std::string(key) == "time_ms" ? 1e3 : 1.0);
      j.erase(key);
    }
    answer_text = j.dump();
  }
  try {
    out.answer = answer_from_text(answer_text, out.path).answer;
  } catch (const SceneError& e) {
    out.error = e.what();
  }
  return out;
}

}  // namespace eccd
