#pragma once
// Animations: every checked pair of bodies in every frame of an animation
// (docs/animation-format.md), answered in a chosen arithmetic.
//
// Statement. Frame k of an animation is [t_k, t_{k+1}]; in it each body moves
// by the keyframe rule (kernel/keyframe_motion.hpp), so each pair is one
// scene of scene-format.md in the local time τ = (t − t_k)/(t_{k+1} − t_k)
// (pair_frame_scene). animate() runs, frame by frame:
//  1. bounding volumes (paper 001 section 5 uses bounding spheres):
//     for each body a sphere containing its swept volume over the frame:
//     centre m = (c_k + c_{k+1})/2, radius ρ = |c_{k+1} − c_k|/2 + r·δ, with r
//     a bound on |x| over the body's shape in its own frame and δ a bound on
//     ‖D(τ)‖₂ (1 without deformation, else max over the two keys of ‖D‖_F,
//     the norm being convex); the rotation keeps lengths. Every bound is an
//     exact rational (square roots rounded up), so a pair is dropped only when
//     |m_i − m_j| > ρ_i + ρ_j is proved, in every arithmetic. Candidates come
//     from sweep-and-prune over the bodies (intervals on the x axis, sorted).
//  2. the separating plane kept from the previous frame (paper 000 section 4:
//     frame coherence), checked over the whole frame by api/separate.hpp's
//     plane_separates_on_frame in the run's arithmetic, after a first check in
//     intervals from prepared numbers (KeptPlaneCheck below; double and
//     certified runs of 3D animations); compiled only when that
//     header exists (the contract of session 25), otherwise this stage settles
//     nothing and AnimationResult::plane_stage_built is false. A plane is
//     trusted for the frame it was checked on, never beyond.
//  3. the continuous test: eccd::solve (api/solve.hpp) on the pair-frame's
//     scene in the run's arithmetic; first contact by default (the first
//     collision interval: 3D SolveOptions::first_contact; 2D the whole answer,
//     Variant::answer, cut to its first interval, since 003's Variant 2 gives
//     the first root of Δ, a candidate, and no interval), the whole answer
//     with all_intervals. A pair-frame with a non-empty collision set is an
//     event; one whose answer has undecided instants (floating: the error
//     bound cannot decide; exact: a budget ran out) goes to `undecided` with
//     the reasons, never to the events.
// Instants are mapped to global time t = t_k + τ(t_{k+1} − t_k) exactly: a
// certified bracket [lo, hi] becomes [t_k + lo·Δ, t_k + hi·Δ] (Δ > 0).
// Events are ordered by frame, then by the positions of the pair's bodies in
// `bodies`. Stage 1 runs frame by frame; stages 2 and 3 run pair by pair (each
// pair's surviving frames in order, so that the plane kept from frame k − 1 is
// at hand in frame k; a frame dropped by stage 1 in between forgets it), the
// pairs on a pool of `threads` std::threads, longest first; results are stored
// by (frame, pair), so the output does not depend on the schedule. `shard_index`/`shard_count` (the command line's
// --shard i/n) keeps the i-th of n contiguous blocks of frames (contiguous so that kept planes carry from frame to
// frame inside a shard). Requirements: the animation is exact (rationals); the arithmetic of the continuous test is the
// caller's (SolveOptions::arith).
#include "api/options.hpp"
#include "io/animation_reader.hpp"
#include "kernel/answer.hpp"
#include "kernel/plane_frame_check.hpp"
#include "kernel/scene.hpp"
#include "number/running_error.hpp"

#include <nlohmann/json.hpp>

#include <array>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace eccd {

inline constexpr const char* kAnimationAnswerFormat = "ellipse-ccd-animation-answer/1";

struct AnimateOptions {
  SolveOptions solve;                            // the arithmetic (and budget) of the continuous test
  bool all_intervals = false;                    // false: first contact only
  int threads = 2;                               // >= 1
  std::size_t shard_index = 0, shard_count = 1;  // 0 <= index < count
  bool planes = true;        // false: skip stage 2 (no plane kept or built; --no-planes, 000 Table 1's "without")
  bool keep_tested = false;  // keep every continuous test's local answer (AnimationResult::tested; for tests)
  // Called on the calling thread about every 0.1 s and at the end: (pair-frames of stages 2-3 done, of this run).
  std::function<void(std::size_t, std::size_t)> progress;
};

struct PairFrameAnswer {
  std::size_t frame = 0, body_a = 0, body_b = 0;  // body_a < body_b, positions in Animation::bodies
  Answer answer;                                  // in global time
  Answer local;                                   // the scene's own answer, in the local time τ
};
struct PairFrameUndecided {
  std::size_t frame = 0, body_a = 0, body_b = 0;
  std::string why;
};
struct FrameSummary {
  std::size_t frame = 0;
  std::size_t pairs = 0;             // checked pairs in the frame
  std::size_t bounding_volumes = 0;  // settled by stage 1
  std::size_t separating_plane = 0;  // settled by stage 2
  std::size_t continuous_test = 0;   // settled by stage 3 (including undecided ones)
  std::size_t events = 0, undecided = 0;
  double seconds = 0;  // stage 1 of the frame plus the work of its pair-frames (thread time, summed)
};

struct AnimationResult {
  std::string animation, file, arithmetic;
  int dim = 3;
  std::size_t frames = 0;           // frames of the animation
  std::size_t pairs_per_frame = 0;  // checked pairs per frame
  std::vector<std::string> body_names;
  std::size_t shard_index = 0, shard_count = 1;
  std::vector<FrameSummary> per_frame;  // the frames this run did, in order
  std::vector<PairFrameAnswer> events;
  std::vector<PairFrameUndecided> undecided;
  std::vector<PairFrameAnswer> tested;  // with keep_tested: every pair-frame of stage 3
  std::size_t bounding_volumes = 0, separating_plane = 0, continuous_test = 0;
  bool plane_stage_built = false;
  bool planes_disabled = false;  // AnimateOptions::planes was false ("separating_plane_stage": "off")
  bool all_intervals = false;
  double seconds = 0;
};

// Stage 2's first check, from numbers prepared once per animation: each
// body's adj(Q) and each key pose's orientation (taken the shorter way round
// from the key before) and centre, rounded to Bounded<double> with their error
// bounds; a kept plane is prepared once when it is kept. check() proves in
// those intervals, without allocation, that the plane separates bodies i and j
// over frame k (kernel/plane_frame_check.hpp, keyframe_plane_check), proves it
// fails (a centre on the wrong side), or says unknown (including for 2D
// animations and bodies with a deformation at either key); animate() then runs
// the general check (api/separate.hpp plane_separates_on_frame) on the
// pair-frame's scene, which is built only then.
class KeptPlaneCheck {
 public:
  using B = Bounded<double>;
  using Plane = std::array<B, 4>;
  explicit KeptPlaneCheck(const Animation& anim);
  Plane prepare(const std::vector<Rational>& normal, const Rational& offset) const;
  FrameSides check(const Plane& plane, std::size_t body_i, std::size_t body_j, std::size_t frame) const;

 private:
  struct Key {
    std::array<B, 4> q, q_next;  // the orientation, and the next key's taken the shorter way round from it
    std::array<B, 3> c;
  };
  bool ok_ = false;
  std::vector<std::array<std::array<B, 4>, 4>> adj_;
  std::vector<std::vector<Key>> keys_;
  std::vector<bool> rigid_;  // no deformation at any key
};

// The scene of bodies i and j (i != j) in frame k, in local time τ.
Scene pair_frame_scene(const Animation& anim, std::size_t body_i, std::size_t body_j, std::size_t frame);

// Throws std::invalid_argument for bad options (threads < 1, bad shard) and
// for a request the pipeline refuses.
AnimationResult animate(const Animation& anim, const AnimateOptions& options = {});

// The spec's answer object (docs/animation-format.md, "The answer of an
// animation"), plus "mode", "separating_plane_stage", "per_frame", "seconds",
// and in each event "local_answer": the same answer in the local time τ of the
// pair-frame's scene (animation-format.md: "given in the local time τ and, for
// people, also in the global time t").
nlohmann::ordered_json animation_result_to_json(const AnimationResult& result);

// The bounding sphere of body b's swept volume in frame k (stage 1): centre and
// a rational radius bound, both exact. Exposed for tests.
struct BoundingSphere {
  std::vector<Rational> centre;
  Rational radius;
};
BoundingSphere swept_bounding_sphere(const Animation& anim, std::size_t body, std::size_t frame);

// The two bounds stage 1 uses, for the per-pose mode (api/pose_check.hpp): a
// rational r >= |x| over body b's solid in its own frame, and a rational
// >= ‖D‖₂ of a key pose's deformation (1 without one). At pose k the body lies
// in the ball of centre c_k and radius r·key_deformation_bound(pose k).
Rational body_shape_radius(const Animation& anim, std::size_t body);
Rational key_deformation_bound(const KeyPose& pose, int dim);

}  // namespace eccd
