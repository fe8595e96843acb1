#pragma once
// The replay log's uses, for any scalar the log was made with: record a run, replay a log and
// compare every decision, reach a moment of a log through its nearest keyframe, and walk its
// decisions. The scalar is chosen from the log's header; callers see plain values.
#include <cstdint>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "gizmo/core/math/precision.hpp"
#include "gizmo/core/run/run.hpp"
#include "gizmo/replay/log_file.hpp"
#include "gizmo/replay/log_header.hpp"
#include "gizmo/replay/record_codec.hpp"

namespace gizmo::replay {

// --- recording -------------------------------------------------------------------------------
struct RecordResult {
  RunSummary summary;
  bool completed = true;
  std::string error;  // why the run stopped early (the log says so too)
};
// Runs the request in the chosen scalar and sends the log to sink. A run that stops with an
// error still closes its log (completed = false). boardWarnings are the board reader's warnings
// (io::format of each), kept in the header so that a run of a leniently read board says so.
RecordResult recordRun(const RunRequest& request, const PrecisionChoice& precision, ChunkSink& sink,
                       const std::vector<std::string>& boardWarnings = {});
// The header frame's payload recordRun writes for `request` (a log whose decisions a Recorder
// gathered as the run went, before its inputs and duration were known: `gizmo play`), in double,
// `board` being the board the run is played on; with a parent, the header of a branch log
// (recordBranch's, for a branch played live). The parameters are the board's: no board is built
// again, so that the header can be written when memory has run short (docs/play.md, "Memory").
std::vector<std::uint8_t> recordHeader(const RunRequest& request, const GameBoard<double>& board,
                                       const std::vector<std::string>& boardWarnings = {},
                                       const std::optional<BranchOrigin>& parent = std::nullopt);

// --- plain views of decoded values -----------------------------------------------------------
struct Exact {
  double value = 0;
  std::string text;  // the exact value (hex float)
};
struct BallView {
  GizmoId ball = kNoGizmo;
  std::string name;
  Exact x, y, vx, vy;  // for an executed event: position, and velocity after
  Exact vxBefore, vyBefore;
};
struct DecisionView {
  std::uint64_t index = 0;       // decisions before this one in the log
  std::uint64_t eventIndex = 0;  // events executed before this one
  DecisionType type = DecisionType::Tick;
  Exact time;  // the board time the decision was made at (never decreases along a log)
  // scheduled, removed, executed
  Exact eventTime;
  EventKind kind = EventKind::EndOfTick;
  GizmoId a = kNoGizmo, b = kNoGizmo;
  std::int32_t feature = -1;
  std::uint64_t sequence = 0;
  std::vector<BallView> balls;  // executed: the balls it changed
  // trigger (gizmo → other), action (gizmo), rule (gizmo, other), input (key, direction)
  GizmoId gizmo = kNoGizmo, other = kNoGizmo;
  int key = 0;
  KeyDirection direction = KeyDirection::Down;
  ModelRule rule = ModelRule::FrictionApplied;
};

struct OpenedLog {
  LogReader reader;
  LogHeader header;
  RunRequest request;
  PrecisionChoice precision;
  std::vector<std::string> gizmoNames;  // by id, as the board builds them
};
// A gizmo's name from a log's gizmoNames: a ball a spawner added has the name the board gives it
// (spawnedBallName); an id the board never had is shown as #id, and none as "".
std::string gizmoName(const std::vector<std::string>& names, GizmoId id);
// Reads a log's header and finds its chunks; throws FormatError (with the path) when it is not a
// readable log.
OpenedLog openLog(const std::string& path);
OpenedLog openLog(std::unique_ptr<ByteSource> source, bool verifyChecksums = true);

// A log's decisions one at a time, in order, starting with the first chunk that may hold
// decisions at or after `fromTime`. next() throws FormatError on a damaged chunk.
class DecisionStream {
 public:
  explicit DecisionStream(const OpenedLog& log, double fromTime = -1);
  ~DecisionStream();
  DecisionStream(DecisionStream&&) noexcept;
  std::optional<DecisionView> next();

  class Source;  // the decoder for the log's scalar

 private:
  std::unique_ptr<Source> source_;
};

// --- replaying -------------------------------------------------------------------------------
struct StateView {
  Exact time;
  std::uint64_t events = 0;
  std::vector<BallView> balls;     // every ball: position and velocity at `time`
  std::vector<std::string> queue;  // the pending events, earliest first, one line each
};
struct ReplayReport {
  bool identical = true;
  bool byDigests = false;       // identity was established from the chunks' digests and keyframes
  std::uint64_t decisions = 0;  // compared
  std::uint64_t events = 0;
  std::string note;  // e.g. the log was cut off and only its prefix was compared
  // At the first difference:
  std::optional<DecisionView> logDecision, runDecision;  // absent when one side had ended
  std::string where;                                     // what differs, in words
  std::optional<StateView> logState, runState;
};
// How a replay compares the run with the log. By digests: the run is made again without encoding,
// and each chunk's decisions are checked against the chunk's digest in the index and each
// keyframe against the run's state; only when something differs (or the log has no index) is the
// run encoded and compared record by record, which finds the first differing decision. Records:
// always record by record.
enum class ReplayMethod : std::uint8_t { Digests, Records };

ReplayReport replayLog(const OpenedLog& log, ReplayMethod method = ReplayMethod::Digests);

// The state after `events` events (or at board time `time`), reached from the nearest keyframe.
struct SeekTarget {
  std::optional<std::uint64_t> events;
  std::optional<double> time;
};
StateView seekLog(const OpenedLog& log, const SeekTarget& target);

// The board a double log's run starts from, for those who run it again themselves (gizmo verify
// --certify): as built, its keys scheduled, or a branch log's first keyframe restored onto it;
// with the ticks and events done before it (0 but in a branch log). Throws FormatError for a log
// of another scalar.
struct RunStartBoard {
  std::unique_ptr<GameBoard<double>> board;
  std::uint64_t ticksDone = 0;
  std::uint64_t eventsDone = 0;
};
RunStartBoard startBoardInDouble(const OpenedLog& log);

// The state a log's run starts from, rounded to doubles, for drawing it (gizmo render): the board
// as built at 0, or a branch log's first keyframe. Each ball's position, velocity and
// acceleration there and whether it is held; each flipper's swing (progress s0 at t0, moving at
// direction, docs/physics.md §2) and each spinner's turn.
struct StartView {
  std::uint64_t events = 0;
  double time = 0;
  struct Ball {
    GizmoId id = kNoGizmo;
    double x = 0, y = 0, vx = 0, vy = 0, ax = 0, ay = 0;
    bool captured = false;
  };
  std::vector<Ball> balls;
  struct Swing {
    GizmoId id = kNoGizmo;
    double t0 = 0, s0 = 0;
    int direction = 0, lastDirection = 1;
  };
  std::vector<Swing> flippers;
  struct Turn {  // a spinner: its cross at phase (radians past a quarter turn) at t0, turning or not
    GizmoId id = kNoGizmo;
    double t0 = 0, phase = 0;
    bool turning = false;
  };
  std::vector<Turn> spinners;
};
StartView startView(const OpenedLog& log);

// --- branching ---------------------------------------------------------------------------------
// A run taken over at a moment of a log (`gizmo record --from`): the branch goes on from that
// moment with new key input, and its log (format version 5) stands alone: its header names the
// parent, its first chunk's keyframe is the parent's state at the last tick boundary at or before
// the branch point, and its records go on from there (docs/replay-format.md, "Branch logs").
struct BranchRequest {
  SeekTarget at;  // the branch point: after this many of the parent's events, or at this board time
  // The key input from the branch point on, at board times. Keys earlier than the branch point are
  // left out, and so are keys at its very time that the parent had already applied then, so that
  // the parent's own key script, given whole, goes on as the parent did.
  std::vector<TimedKey> keys;
  std::optional<double> duration;  // the board time the branch runs to; the parent's by default
};
struct BranchResult {
  RecordResult record;
  BranchOrigin origin;            // the parent's digest and the branch point's event index
  Exact time;                     // the branch point's board time
  std::uint64_t startEvents = 0;  // the parent's events at the tick boundary the branch log starts from
  std::size_t keysLeftOut = 0;    // keys of the request before the branch point
};
// A branch point or branch request that cannot be served: the parent is cut off, the point lies
// beyond its end (or before a branch log's start), the branch would end before its point.
class BranchError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};
// Everything that can fail is checked before the sink is given the header, so a refused branch
// leaves no file. Throws BranchError, or FormatError for a damaged parent.
BranchResult recordBranch(const OpenedLog& parent, const BranchRequest& request, ChunkSink& sink);

// --- two logs ----------------------------------------------------------------------------------
struct DiffReport {
  bool parted = false;
  bool sameScalar = true;     // values are compared exactly only between logs of one scalar
  std::uint64_t matched = 0;  // decisions alike before the logs part
  // The first decision compared: 0, or where a branch starts (a branch log holds nothing before).
  std::uint64_t firstDecision = 0;
  std::string where;                          // what differs at the parting decision
  std::vector<std::string> notes;             // e.g. the logs are of different boards or models
  std::vector<DecisionView> before;           // the last alike decisions (of the first log)
  std::optional<DecisionView> first, second;  // the parting decisions; absent where a log ended
  std::vector<DecisionView> afterFirst, afterSecond;
  double maxTimeDifference = 0;      // over alike decisions: event times
  double maxPositionDifference = 0;  // over alike executed events: ball positions
  // With counts: decisions of each type in each log (the whole logs are read).
  std::vector<std::pair<std::string, std::pair<std::uint64_t, std::uint64_t>>> counts;
};
DiffReport diffLogs(const OpenedLog& first, const OpenedLog& second, std::size_t context, bool counts);

}  // namespace gizmo::replay
