#pragma once
// Which *.json files under a folder are scenes (never skip a scene
// silently; cases/ also holds animations, whose "format" is
// ellipse-ccd-animation/1). Used by `eccd regress`, `eccd report` (the cases
// and --scenes folders) and `eccd table`.
//
// A file is read and parsed whole: an object whose "format" is the scene
// format is a scene; a file that does not parse, or an object that looks like
// a scene (a "format" starting with "ellipse-ccd-scene", or the keys "dim",
// "a" and "b") with another or no format, is Broken (the caller reports it as
// an error naming the file); other JSON (animations, certificates, answers,
// plot data: another "format") is not a scene and is left out.
#include "io/scene_error.hpp"
#include "io/scene_reader.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <string>

namespace eccd {

enum class FileKind { Scene, NotScene, Broken };

// `text` receives the file's bytes (read once: the bytes checked are the bytes run), `why` what is wrong (Broken).
inline FileKind classify_file(const std::filesystem::path& p, std::string& text, std::string& why) {
  try {
    text = read_file_bytes(p.string());
  } catch (const SceneError& e) {
    why = e.what();
    why = why.substr(std::min(why.size(), p.string().size() + 2));  // without the path (the caller adds it)
    return FileKind::Broken;
  }
  nlohmann::json j = nlohmann::json::parse(text, nullptr, false);
  if (j.is_discarded()) {
    why = "not a JSON text (malformed or truncated): cannot tell whether it is a scene";
    return FileKind::Broken;
  }
  if (!j.is_object()) return FileKind::NotScene;
  auto f = j.find("format");
  const std::string scene_format = "ellipse-ccd-scene/1";
  if (f != j.end() && f->is_string() && f->get<std::string>() == scene_format) return FileKind::Scene;
  const bool scene_like =
      (f != j.end() && f->is_string() && f->get<std::string>().rfind("ellipse-ccd-scene", 0) == 0) ||
      (j.contains("dim") && j.contains("a") && j.contains("b"));
  if (scene_like) {
    std::string got = f == j.end() ? std::string("no \"format\" key") : "\"format\" " + f->dump().substr(0, 80);
    why = "looks like a scene but has " + got + " (a scene has \"format\": \"" + scene_format + "\")";
    return FileKind::Broken;
  }
  return FileKind::NotScene;
}

}  // namespace eccd
