#pragma once
// SceneError: a scene (or another input file) that cannot be read, with the
// message "FILE: PLACE: what is wrong" (io/scene_reader.hpp says how PLACE is
// written). Without JSON, so that the API's header (api/solve.hpp) can name it.
#include <stdexcept>

namespace eccd {

struct SceneError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace eccd
