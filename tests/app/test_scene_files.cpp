// Which *.json files are scenes (app/scene_files.hpp): classify_file reads a
// file whole and says Scene (an object with "format": "ellipse-ccd-scene/1"),
// NotScene (other JSON: animations, answers, arrays, numbers) or Broken (a
// file that does not parse, cannot be read, or an object that looks like a
// scene — a format starting with "ellipse-ccd-scene", or the keys dim, a, b —
// without the scene format), with the reason, without the path, for Broken;
// `text` holds the bytes read. Every scene of cases/ is a Scene, every
// animation there is NotScene.
#include "app/scene_files.hpp"

#include <catch2/catch.hpp>

#include <unistd.h>

#include <fstream>

namespace ECCD_UNITY_ID {
using namespace eccd;
namespace fs = std::filesystem;

namespace {
struct Dir {
  fs::path p = fs::temp_directory_path() / ("eccd-scene-files-" + std::to_string(::getpid()));
  Dir() {
    fs::remove_all(p);
    fs::create_directories(p);
  }
  ~Dir() {
    std::error_code ec;
    fs::remove_all(p, ec);
  }
  fs::path put(const std::string& name, const std::string& text) const {
    std::ofstream(p / name, std::ios::binary) << text;
    return p / name;
  }
};
FileKind kind(const fs::path& f, std::string* why = nullptr) {
  std::string text, w;
  const FileKind k = classify_file(f, text, w);
  if (why) *why = w;
  return k;
}
}  // namespace

TEST_CASE("scene files: scenes, other JSON and broken files", "[app][scene-files]") {
  Dir d;
  const std::string scene = R"({"format": "ellipse-ccd-scene/1", "dim": 2, "a": {}, "b": {}})";
  std::string text, why;
  CHECK(classify_file(d.put("s.json", scene), text, why) == FileKind::Scene);
  CHECK(text == scene);  // the bytes read
  CHECK(why.empty());
  // A scene that the reader would refuse is still a scene (the reader reports it).
  CHECK(kind(d.put("bad-scene.json", R"({"format": "ellipse-ccd-scene/1"})")) == FileKind::Scene);
  CHECK(kind(d.put("anim.json", R"({"format": "ellipse-ccd-animation/1", "bodies": []})")) == FileKind::NotScene);
  CHECK(kind(d.put("answer.json", R"({"collides": false, "intervals": []})")) == FileKind::NotScene);
  CHECK(kind(d.put("array.json", "[1, 2, 3]")) == FileKind::NotScene);
  CHECK(kind(d.put("number.json", "42")) == FileKind::NotScene);
  CHECK(kind(d.put("dim-only.json", R"({"dim": 2, "a": {}})")) == FileKind::NotScene);  // no "b"
  CHECK(kind(d.put("fmt-number.json", R"({"format": 1})")) == FileKind::NotScene);

  CHECK(kind(d.put("trunc.json", R"({"format": "ellipse-ccd-scene/1", "dim": )"), &why) == FileKind::Broken);
  CHECK(why == "not a JSON text (malformed or truncated): cannot tell whether it is a scene");
  CHECK(kind(d.put("empty.json", ""), &why) == FileKind::Broken);
  CHECK(kind(d.put("v2.json", R"({"format": "ellipse-ccd-scene/2", "dim": 2})"), &why) == FileKind::Broken);
  CHECK(why ==
        "looks like a scene but has \"format\" \"ellipse-ccd-scene/2\" (a scene has \"format\": "
        "\"ellipse-ccd-scene/1\")");
  CHECK(kind(d.put("noformat.json", R"({"dim": 3, "a": {}, "b": {}})"), &why) == FileKind::Broken);
  CHECK(why.find("looks like a scene but has no \"format\" key") == 0);
  CHECK(kind(d.put("other.json", R"({"format": "mine/1", "dim": 3, "a": {}, "b": {}})"), &why) == FileKind::Broken);
  CHECK(why.find("\"format\" \"mine/1\"") != std::string::npos);
  // A file that cannot be read: the reason without the path.
  CHECK(kind(d.p / "missing.json", &why) == FileKind::Broken);
  CHECK(!why.empty());
  CHECK(why.find(d.p.string()) == std::string::npos);
  fs::create_directories(d.p / "dir.json");
  CHECK(kind(d.p / "dir.json", &why) == FileKind::Broken);
}

TEST_CASE("scene files: the scenes and animations of cases/", "[app][scene-files]") {
  int scenes = 0, animations = 0;
  for (const auto& e : fs::recursive_directory_iterator(std::string(ECCD_SOURCE_DIR) + "/cases")) {
    if (e.path().extension() != ".json") continue;
    const bool animation = e.path().parent_path().filename() == "animations";
    INFO(e.path());
    CHECK(kind(e.path()) == (animation ? FileKind::NotScene : FileKind::Scene));
    (animation ? animations : scenes)++;
  }
  CHECK(scenes > 20);
  CHECK(animations >= 2);
}

}  // namespace ECCD_UNITY_ID
