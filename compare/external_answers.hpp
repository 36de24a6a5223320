#pragma once
// External engines in the report: `eccd report --external
// NAME=DIR` gives a user's engine (FCL driven by their own code, their
// simulator, another library) its own rows in every table and plot, judged
// against the exact answer like eccd's own pipelines.
//
// Statement. DIR holds one answer file per scene, named after the scene's
// "name" key: DIR/<scene name>.json. A file is any answer `eccd judge` reads
// (api/judge.hpp: a bare answer object {"collides", "intervals",
// "first_contact", "contacts"}, a scene file with an "answer" key, or the
// output of `eccd solve --json`), in the scene format's answer form
// (docs/scene-format.md "The answer"): decimals, or rational brackets. An
// optional top-level number "time_us" (or "time_ms") is the engine's own time
// for the query; without it the row's time is "not measured". A scene with no
// file in DIR gets no row for that engine (the report counts the missing
// ones); a file that cannot be read gives a row with outcome "error" and the
// reader's message (file and JSON place), never a guess.
// The comparison is compare/metrics.hpp's answer_metrics, that is THE one
// answer comparison (api/answer_difference.hpp), against the exact answer.
// Requirements: none (reads files; JSON stays in the .cpp).
#include "api/solution.hpp"

#include <optional>
#include <string>

namespace eccd {

struct ExternalEngine {
  std::string name;  // the rows' pipeline label is "ext:" + name
  std::string dir;   // the folder of answer files
};

// "NAME=DIR": NAME of letters, digits, '_', '-', '.' (at most 40), DIR an
// existing folder. Throws std::invalid_argument saying what is wrong.
ExternalEngine parse_external(const std::string& spec);

// The engine's answer for one scene.
struct ExternalAnswer {
  std::optional<Answer> answer;  // none: the file could not be read (see error)
  std::string error;             // the reader's message: file, JSON place, what is wrong
  double time_us = -1;           // the engine's own time, < 0 when the file does not give it
  std::string path;
};

// DIR/<scene name>.json read as an answer; nullopt when there is no such file.
std::optional<ExternalAnswer> read_external_answer(const ExternalEngine& engine, const std::string& scene_name);

}  // namespace eccd
