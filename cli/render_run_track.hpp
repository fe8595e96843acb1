#pragma once
// Everything a picture or the player needs from one log, in plain arrays: every executed event,
// each ball's motion, each flipper's swing, and the reports that came with each event (triggers,
// actions, key inputs, model rules).
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "gizmo/replay/replay.hpp"
#include "render_ball_paths.hpp"
#include "render_flipper_swings.hpp"

namespace gizmo::cli {

// A report made while an event ran. `type` is the DecisionType; x and y are, by type: trigger
// (source, target), action (gizmo, −1), input (key, direction 0 down / 1 up), rule (gizmo, other;
// `rule` is its ModelRule).
struct EventNote {
  std::uint32_t event = 0;
  std::uint8_t type = 0;
  std::uint8_t rule = 0;
  std::int32_t x = 0, y = 0;
};

struct BallTrack {
  GizmoId id = kNoGizmo;
  std::string name;
  std::vector<PathPiece> pieces;
};

struct RunTrack {
  MotionModel model = MotionModel::Ballistic;
  std::string precision;
  double duration = 0;           // as requested
  double startTime = 0;          // where the log's run starts: 0, or a branch log's first keyframe
  std::uint64_t firstEvent = 0;  // the events before that start (a branch log's first keyframe)
  double endTime = 0;            // the time of the last event read
  double tolerance = 0;
  std::string truncation;               // why the log stops early, when it does
  std::vector<std::string> gizmoNames;  // by id
  // Executed events, in order: the i-th event is the one after which i + 1 events have run (in a
  // branch log, i + 1 events after its start).
  std::vector<double> eventTime;
  std::vector<std::uint8_t> eventKind;
  std::vector<std::int32_t> eventA, eventB, eventFeature;
  std::vector<BallTrack> balls;
  // Each flipper's swing anchors, and each spinner's (the seconds it has turned, direction 1 while
  // it turns: the player draws it at that times its rate).
  std::map<GizmoId, std::vector<SwingAnchor>> flippers;
  std::vector<EventNote> notes;
  // Where each ball was at each collision (the log's own values), for pictures.
  std::vector<Vec2<double>> collisionPoints;
};

// Reads every decision of the log (throws FormatError on a damaged chunk). Ball pieces that stay
// within `tolerance` L of the piece before them are left out (render_ball_paths.hpp).
RunTrack trackRun(const replay::OpenedLog& log, double tolerance);

}  // namespace gizmo::cli
