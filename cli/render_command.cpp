// `gizmo render`: checks what it is given, reads it, and writes one whole file (see
// render_command.hpp). Bad input is refused with exit code 2 before anything is written.
#include "render_command.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>

#include "board_input.hpp"
#include "gizmo/io/board_writer.hpp"
#include "log_view.hpp"
#include "render_board_svg.hpp"
#include "render_output.hpp"
#include "render_player_html.hpp"

namespace gizmo::cli {
namespace {

bool endsWith(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// A log starts with its magic; anything else is taken for a board file.
bool isLogFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  char magic[8] = {};
  return in.read(magic, sizeof magic) && std::string(magic, sizeof magic) == "GIZMOLOG";
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

int renderPlayer(const RenderOptions& o, double tolerance) {
  if (!o.trace.empty()) return fail("--trace draws paths on a picture (-o FILE.svg); the player shows them itself");
  if (o.input.empty() || !isLogFile(o.input))
    return fail((o.input.empty() ? std::string("no log given") : o.input + ": not a replay log") +
                "; the player plays a log (gizmo record … -o run.gzlog), a board renders to a picture (-o board.svg)");
  int code = kExitOk;
  const std::optional<replay::OpenedLog> log = openLogFor("render", o.input, code);
  if (!log) return code;
  std::optional<replay::OpenedLog> other;
  if (!o.compare.empty()) {
    other = openLogFor("render", o.compare, code);
    if (!other) return code;
    if (other->header.board != log->header.board)
      return fail(o.compare + ": not a run of the same board as " + o.input + " (--compare lays runs of one board over each other)");
  }
  std::vector<PlayerRun> runs;
  std::optional<Parting> parting;
  try {
    runs.push_back(PlayerRun{fileName(o.input), trackRun(*log, tolerance)});
    if (other) {
      runs.push_back(PlayerRun{fileName(o.compare), trackRun(*other, tolerance)});
      parting = partingOf(*log, *other);
    }
  } catch (const std::exception& e) {
    return fail(e.what());
  }
  writeFileWhole(o.output, playerHtml(drawingOf(log->request.board), runs, parting));
  if (other) return finishWithCutOffLogs("render", kExitOk, {&*log, &*other}, {o.input, o.compare});
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
      board = loadBoard(o.input).spec;
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
