// `gizmo render`: checks what it is given, reads it, and writes one whole file (see
// render_command.hpp). Bad input is refused with exit code 2 before anything is written.
#include "render_command.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string_view>

#include "board_input.hpp"
#include "crosscheck_command.hpp"
#include "gizmo/io/board_writer.hpp"
#include "gizmo/verify/box2d_mapping.hpp"
#include "log_view.hpp"
#include "render_board_svg.hpp"
#include "render_output.hpp"
#include "render_path_file.hpp"
#include "render_path_overlay.hpp"
#include "render_player_html.hpp"

namespace gizmo::cli {
namespace {

bool endsWith(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

std::string fileName(const std::string& path) { return std::filesystem::path(path).filename().string(); }

int fail(const std::string& message) {
  std::cerr << "gizmo render: " << message << '\n';
  return kExitBadInput;
}

std::optional<Parting> partingOf(const replay::OpenedLog& first, const replay::OpenedLog& second) {
  const replay::DiffReport r = replay::diffLogs(first, second, 0, false);
  if (!r.parted) return std::nullopt;
  Parting p;
  p.where = r.where;
  p.matchedDecisions = r.matched;
  if (r.first) p.firstEvents = r.first->eventIndex;
  if (r.second) p.secondEvents = r.second->eventIndex;
  p.time = r.first ? r.first->time.value : r.second ? r.second->time.value : 0.0;
  return p;
}

// What --compare names: another log, a path file, or Box2D run here.
struct Comparison {
  std::optional<replay::OpenedLog> log;
  std::optional<PathFile> path;
  std::string label;
};

constexpr std::string_view kBox2dPrefix = "box2d:";

// Box2D's run of the log's own request (board, keys, model, duration) at the step size asked for,
// with crosscheck's defaults (bullets, restitution threshold 0).
int box2dComparison(const replay::OpenedLog& log, const std::string& step, Comparison& out) {
  const std::optional<double> dt = parseStepSize(step);
  if (!dt) return fail("--compare box2d:" + step + ": not a step size from 1e-5 to 0.1 s (a number or 1/N)");
  if (log.request.duration / *dt > kMaxBox2dSteps)
    return fail("--compare box2d:" + step +
                ": the log's run is too long for that step size (more than 1e7 Box2D steps)");
  if (const std::optional<std::string> why = verify::box2dCannotModel(log.request.board))
    return fail("--compare: " + *why);
  verify::Box2dOptions options;
  options.dt = *dt;
  const verify::RunRecord run = verify::runBox2d(log.request, options);
  out.path = box2dPathFile(log.request, "", options, run.samples);
  out.label = "Box2D at " + step + " s";
  return kExitOk;
}

int pathComparison(const replay::OpenedLog& log, const RenderOptions& o, Comparison& out) {
  try {
    out.path = readPathFile(o.compare);
  } catch (const PathFileError& e) {
    return fail(e.what());
  }
  if (out.path->boardChecksum != log.header.boardHash) {
    const std::string theirs = (out.path->boardName.empty() ? "" : out.path->boardName + ", ") + "checksum " +
                               checksumText(out.path->boardChecksum);
    return fail(o.compare + ": a path of another board (" + theirs + ") than " + o.input + "'s (checksum " +
                checksumText(log.header.boardHash) + "); gizmo crosscheck BOARD --dt STEP --path-out FILE makes one");
  }
  if (out.path->keysChecksum != keysChecksum(log.request.keys))
    return fail(o.compare + ": a path run with another key script than " + o.input +
                "'s; give gizmo crosscheck the same --keys file as gizmo record");
  out.label = fileName(o.compare);
  return kExitOk;
}

int comparisonOf(const replay::OpenedLog& log, const RenderOptions& o, Comparison& out) {
  if (o.compare.rfind(kBox2dPrefix, 0) == 0) return box2dComparison(log, o.compare.substr(kBox2dPrefix.size()), out);
  std::error_code error;
  if (std::filesystem::is_regular_file(o.compare, error) && !isLogFile(o.compare)) {
    if (isPathFile(o.compare)) return pathComparison(log, o, out);
    return fail(o.compare +
                ": neither a replay log nor a path file (--compare takes a log of the same board, a path "
                "file from gizmo crosscheck --path-out, or box2d:STEP)");
  }
  int code = kExitOk;
  out.log = openLogFor("render", o.compare, code);
  if (!out.log) return code;
  if (out.log->header.board != log.header.board)
    return fail(o.compare + ": not a run of the same board as " + o.input +
                " (--compare lays runs of one board over each other)");
  out.label = fileName(o.compare);
  return kExitOk;
}

// One line for the person who asked: where our run and the path part, if they do.
void sayParting(const RenderOptions& o, const PathOverlay& overlay) {
  if (overlay.parting)
    std::printf("%s: %s parts from %s at t = %.6g s (%s %.3g L apart, more than %g L)\n", fileName(o.output).c_str(),
                fileName(o.input).c_str(), overlay.label.c_str(), overlay.parting->time, overlay.parting->ball.c_str(),
                overlay.parting->distance, kPartingDistance);
  else
    std::printf("%s: %s and %s stay within %g L of each other\n", fileName(o.output).c_str(), fileName(o.input).c_str(),
                overlay.label.c_str(), kPartingDistance);
}

int renderPlayer(const RenderOptions& o, double tolerance) {
  if (!o.trace.empty()) return fail("--trace draws paths on a picture (-o FILE.svg); the player shows them itself");
  if (o.input.empty() || !isLogFile(o.input))
    return fail((o.input.empty() ? std::string("no log given") : o.input + ": not a replay log") +
                "; the player plays a log (gizmo record … -o run.gzlog), a board renders to a picture (-o board.svg)");
  int code = kExitOk;
  const std::optional<replay::OpenedLog> log = openLogFor("render", o.input, code);
  if (!log) return code;
  Comparison other;
  if (!o.compare.empty()) {
    try {
      code = comparisonOf(*log, o, other);
    } catch (const std::exception& e) {
      return fail(o.compare + ": " + e.what());
    }
    if (code != kExitOk) return code;
  }
  std::vector<PlayerRun> runs;
  std::optional<Parting> parting;
  std::optional<PathOverlay> overlay;
  try {
    runs.push_back(PlayerRun{fileName(o.input), trackRun(*log, tolerance)});
    if (other.log) {
      runs.push_back(PlayerRun{other.label, trackRun(*other.log, tolerance)});
      parting = partingOf(*log, *other.log);
    }
    if (other.path) overlay = overlayOf(*other.path, other.label, runs.front().track, tolerance);
  } catch (const std::exception& e) {
    return fail(e.what());
  }
  writeFileWhole(o.output, playerHtml(drawingOf(log->request.board), runs, parting, overlay ? &*overlay : nullptr));
  if (overlay) sayParting(o, *overlay);
  if (other.log) return finishWithCutOffLogs("render", kExitOk, {&*log, &*other.log}, {o.input, o.compare});
  return finishWithCutOffLogs("render", kExitOk, {&*log}, {o.input});
}

int renderPicture(const RenderOptions& o, double tolerance) {
  if (!o.compare.empty()) return fail("--compare lays two runs over each other in the player (-o FILE.html)");
  int code = kExitOk;
  std::optional<replay::OpenedLog> trace;
  if (!o.trace.empty()) {
    trace = openLogFor("render", o.trace, code);
    if (!trace) return code;
  }
  std::optional<replay::OpenedLog> boardLog;
  BoardSpec board;
  if (!o.input.empty() && isLogFile(o.input)) {
    boardLog = openLogFor("render", o.input, code);
    if (!boardLog) return code;
    board = boardLog->request.board;
  } else if (o.input.empty() && trace) {
    board = trace->request.board;  // no board given: the traced run's own
  } else {
    try {
      board = loadBoard(o.input, o.strict).spec;
    } catch (const std::exception& e) {
      return fail(e.what());
    }
  }
  std::optional<RunTrack> track;
  if (trace) {
    if (io::writeTextBoard(board) != trace->header.board)
      return fail(o.trace + ": a run of another board than the one drawn");
    try {
      track = trackRun(*trace, tolerance);
    } catch (const std::exception& e) {
      return fail(o.trace + ": " + e.what());
    }
  }
  writeFileWhole(o.output, boardSvg(drawingOf(board), track ? &*track : nullptr));
  if (trace) return finishWithCutOffLogs("render", kExitOk, {&*trace}, {o.trace});
  return kExitOk;
}

}  // namespace

int renderCommand(const RenderOptions& o) {
  const double tolerance = o.tolerance.value_or(kDefaultRenderTolerance);
  if (!std::isfinite(tolerance) || tolerance < 0 || tolerance > 1)
    return fail("--tolerance must be a distance from 0 to 1 (board units)");
  std::error_code error;
  if (!o.input.empty() && !std::filesystem::is_regular_file(o.input, error)) return fail(o.input + ": no such file");
  try {
    if (endsWith(o.output, ".html")) return renderPlayer(o, tolerance);
    if (endsWith(o.output, ".svg")) return renderPicture(o, tolerance);
    return fail("-o must name a .html file (the replay player) or a .svg file (a picture of the board)");
  } catch (const std::exception& e) {
    return fail(e.what());
  }
}

}  // namespace gizmo::cli
