#pragma once
// A path file: where another engine put each ball of a board after each of its steps. Box2D's
// run is written by `gizmo crosscheck --path-out` and drawn by `gizmo render --compare` over our
// own run (docs/render.md, "Our run against Box2D's"). It is plain text, so that a run can be
// read, diffed and plotted without gizmo:
//
//   gizmo-path 1
//   engine Box2D 2.4.0, bullets on, restitution threshold 0 m/s, 8 velocity / 3 position iterations
//   board f9b7591dec2f3e17 spec-example.txt    checksum64 of the canonical board text (as a log's header)
//   keys 17fb89ee9dcab42a                      checksum64 of the key script's canonical text
//   model ballistic
//   dt 0.0041666666666666666
//   time 10
//   balls B
//   samples
//   0 B 1 11                                   time, ball, x, y: one line per ball per step
//   …
//   end
//
// The `end` line tells a whole file from one cut off at a line's end.
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "gizmo/core/geometry/vec2.hpp"
#include "gizmo/core/run/run.hpp"
#include "gizmo/verify/box2d_world.hpp"

namespace gizmo::cli {

struct PathSample {
  double t = 0;
  Vec2<double> p;
};

struct PathFile {
  std::string engine;  // the engine and its settings, as one line of text
  std::uint64_t boardChecksum = 0;
  std::string boardName;  // for people: the checksum decides which board it is
  std::uint64_t keysChecksum = 0;
  MotionModel model = MotionModel::Ballistic;  // the model of the run it was compared with
  double dt = 0;
  double duration = 0;
  std::vector<std::string> balls;
  std::vector<std::vector<PathSample>> samples;  // per ball, in `balls` order, strictly increasing in time
};

// A path file that does not read: the message starts with "FILE:LINE: ".
class PathFileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

inline constexpr const char* kPathFileMagic = "gizmo-path 1";

// Whether the file starts with the path file's first line (a log starts with its binary magic).
bool isPathFile(const std::string& path);
// Throws PathFileError naming the file and line of the first thing wrong.
PathFile readPathFile(const std::string& path);
std::string pathFileText(const PathFile& file);

// The checksums a path file names its run's board and keys by: the board's is the one a log's
// header holds (checksum64 of io::writeTextBoard).
std::uint64_t boardChecksum(const BoardSpec& board);
std::uint64_t keysChecksum(const std::vector<TimedKey>& keys);
std::string checksumText(std::uint64_t checksum);  // 16 hex digits, as the file writes it

// Box2D's run of `request` at `options.dt` as a path file: `samples` are runBox2d's, one per step
// from time 0; those after the request's duration are left out.
PathFile box2dPathFile(const RunRequest& request, const std::string& boardName, const verify::Box2dOptions& options,
                       const std::vector<verify::TrajectorySample>& samples);

}  // namespace gizmo::cli
