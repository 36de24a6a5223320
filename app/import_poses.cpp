// `eccd import-poses POSES.csv --shapes SHAPES.json [--out ANIM.json]`: a CSV
// of poses (a simulator's or a motion-capture rig's trajectory) and a shapes
// file become an animation file (docs/import-poses.md); the conversion is
// io/pose_import.hpp, the same one the Python builder uses. Exit 2 for a bad
// file (the message names the file, the line and the column) or a bad output
// path; nothing is written then.
#include "app/atomic_write.hpp"
#include "app/commands.hpp"
#include "io/pose_import.hpp"
#include "io/scene_reader.hpp"

#include <filesystem>
#include <iostream>
#include <memory>
#include <stdexcept>

namespace eccd {

Command add_import_poses_command(CLI::App& app) {
  struct Args {
    std::string csv, shapes, out;
  };
  auto args = std::make_shared<Args>();
  Command c;
  c.sub = app.add_subcommand(
      "import-poses",
      "Make an animation file (docs/animation-format.md) from a CSV of poses (lines: time, body, x, y, z, "
      "qw, qx, qy, qz; 2D: time, body, x, y, angle) and a shapes file (docs/import-poses.md).");
  c.sub->add_option("POSES", args->csv, "The CSV of poses; - reads standard input")->required();
  c.sub
      ->add_option("--shapes", args->shapes,
                   "The shapes file: dim, the bodies' names, shapes and groups, the pairs to check")
      ->required();
  c.sub->add_option("--out", args->out, "Write the animation to this file (atomically) instead of standard output");
  c.run = [args]() -> int {
    if (!args->out.empty()) {
      check_output_path("--out", args->out);
      // Replaced only if it is a regular file (never a device, a FIFO or what a symlink points to), and never an input.
      namespace fs = std::filesystem;
      std::error_code ec;
      const fs::file_status st = fs::symlink_status(args->out, ec);
      if (fs::exists(st) && !fs::is_regular_file(st))
        throw std::invalid_argument(
            "--out " + args->out +
            ": not a regular file (a device, a FIFO, a directory or a symlink): nothing is written there");
      for (const std::string& in : {args->csv, args->shapes})
        if (in != "-" && fs::exists(st) && fs::equivalent(in, args->out, ec))
          throw std::invalid_argument("--out " + args->out + ": it is one of the inputs (" + in + ")");
    }
    const SceneSource shapes = read_scene_source(args->shapes);
    const SceneSource csv = read_scene_source(args->csv);
    const Keyframes k = pose_keyframes_from_csv(csv.text, csv.label, shapes_from_text(shapes.text, shapes.label));
    const std::string text = animation_text(animation_json(k, csv.label));
    if (!args->out.empty())
      write_text_atomically(args->out, text);
    else
      std::cout << text;
    return 0;
  };
  return c;
}

}  // namespace eccd
