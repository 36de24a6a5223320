#pragma once
// Animation reader: reads and validates an animation file into an Animation.
//
// Statement. Implements docs/animation-format.md, format
// "ellipse-ccd-animation/1": many ellipses (2D) or ellipsoids (3D) posed at
// common key times t_0 < ... < t_K; between two consecutive key times every
// body moves by the keyframe rule of kernel/keyframe_motion.hpp (paper 001
// section 5), so each pair of bodies in each frame is one scene of
// scene-format.md (api/animate.hpp, pair_frame_scene). Every check raises
// SceneError "FILE: PLACE: what is wrong" with PLACE a JSON pointer, exactly
// as the scene reader (io/scene_reader.hpp: the same strict JSON, numbers,
// shapes and input limits; a JSON number with a fraction part is an error).
// Checked, all exactly (rationals; roots on [0, 1] by exact isolation):
//  - format first; unknown keys at their own place, with the allowed keys;
//  - times: at least two numbers, strictly increasing;
//  - bodies: at least two, each with a unique non-empty name, an optional
//    group (a string), a shape of scene-format.md, and exactly one pose per
//    key time;
//  - a pose: position (dim numbers), orientation (3D [w, x, y, z], 2D [w, z])
//    not zero, optional deformation (dim x dim) with det D > 0;
//  - per body and frame: q(τ) ≠ 0 on [0, 1] (after the shorter-way rule q(τ)
//    cannot vanish: a zero would need q_{k+1} a negative multiple of q_k,
//    which the rule flips; the check is kept so that the rule and the file
//    are never trusted blindly) and det D(τ) ≠ 0 on [0, 1], the message
//    naming the body, the frame and where;
//  - pairs: "all" (the default), "between-groups" (then every body needs a
//    group), or a list of name pairs [["a", "b"], ...] of known, distinct
//    names, each unordered pair at most once; the selection must not be
//    empty.
// Choices where the spec leaves room: "dim" 2 or 3 as in scenes; "name" a
// non-empty string; "note" a string; a deformation equal to the identity is
// the same as none. The checked pairs are kept in the order of `bodies`
// (first body, then second), whatever order a list gives.
// Requirements: GMP rationals, nlohmann json (through io/scene_reader.hpp).
#include "io/scene_error.hpp"
#include "kernel/keyframe_motion.hpp"
#include "number/rational_traits.hpp"

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace eccd {

struct AnimationBody {
  std::string name;
  std::string group;  // "" when the file gives none
  bool has_group = false;
  std::vector<std::vector<Rational>> Q;  // the shape, (dim+1) x (dim+1), in the body's frame
  std::vector<KeyPose> poses;            // one per key time
};

struct Animation {
  std::string path;  // the file label ("" if built in code)
  std::string name, note;
  int dim = 3;
  std::vector<Rational> times;  // t_0 < t_1 < ... < t_K
  std::vector<AnimationBody> bodies;
  std::string pairs_rule = "all";                          // "all" | "between-groups" | "list"
  std::vector<std::pair<std::size_t, std::size_t>> pairs;  // body indices i < j, in the order of bodies
  std::size_t frames() const { return times.empty() ? 0 : times.size() - 1; }
};

inline constexpr const char* kAnimationFormat = "ellipse-ccd-animation/1";

// Throws SceneError "FILE: PLACE: what is wrong".
Animation read_animation(const std::string& path);
Animation animation_from_text(const std::string& json_text, const std::string& label = "<string>");

}  // namespace eccd
