#include "log_view.hpp"

#include <cstdio>
#include <fstream>
#include <iostream>
#include <string_view>

#include "board_input.hpp"
#include "gizmo/replay/format_error.hpp"
#include "gizmo/replay/log_format.hpp"

namespace gizmo::cli {
namespace {

using replay::DecisionType;
using replay::DecisionView;

std::string number(const replay::Exact& x, bool exact) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", x.value);
  return exact ? x.text : std::string(buf);
}

nlohmann::ordered_json exactJson(const replay::Exact& x) { return {{"value", x.value}, {"exact", x.text}}; }

}  // namespace

std::string decisionLine(const DecisionView& d, const std::vector<std::string>& names, bool exact) {
  char head[64];
  std::snprintf(head, sizeof head, "%-9llu ", static_cast<unsigned long long>(d.index));
  std::string line = head + number(d.time, exact) + " " + std::string(replay::decisionTypeName(d.type));
  switch (d.type) {
    case DecisionType::Scheduled:
    case DecisionType::Removed:
    case DecisionType::Executed:
      line += " " + std::string(eventKindName(d.kind)) + " #" + std::to_string(d.sequence);
      if (d.type != DecisionType::Executed) line += " for " + number(d.eventTime, exact);
      if (d.kind == EventKind::Input) {
        line += std::string(d.b ? " up " : " down ") + std::to_string(d.feature);
        break;
      }
      if (d.a != kNoGizmo) line += " " + replay::gizmoName(names, d.a);
      if (d.b != kNoGizmo) line += " " + replay::gizmoName(names, d.b);
      if (d.kind == EventKind::Collision) line += " feature " + std::to_string(d.feature);
      if (d.type == DecisionType::Executed) line += " (event " + std::to_string(d.eventIndex) + ")";
      for (const replay::BallView& b : d.balls)
        line += " | " + b.name + " at (" + number(b.x, exact) + ", " + number(b.y, exact) + ") v (" +
                number(b.vxBefore, exact) + ", " + number(b.vyBefore, exact) + ") -> (" + number(b.vx, exact) + ", " +
                number(b.vy, exact) + ")";
      break;
    case DecisionType::Trigger:
      line += " " + replay::gizmoName(names, d.gizmo) + " -> " + replay::gizmoName(names, d.other);
      break;
    case DecisionType::Action: line += " " + replay::gizmoName(names, d.gizmo); break;
    case DecisionType::Input:
      line += std::string(d.direction == KeyDirection::Up ? " up " : " down ") + std::to_string(d.key);
      break;
    case DecisionType::Rule:
      line += " " + std::string(modelRuleName(d.rule)) + " " + replay::gizmoName(names, d.gizmo);
      if (d.other != kNoGizmo) line += " " + replay::gizmoName(names, d.other);
      break;
    case DecisionType::Tick:
    case DecisionType::Time: break;
  }
  return line;
}

nlohmann::ordered_json decisionJson(const DecisionView& d, const std::vector<std::string>& names) {
  nlohmann::ordered_json j{{"index", d.index}, {"type", replay::decisionTypeName(d.type)}, {"time", exactJson(d.time)}};
  switch (d.type) {
    case DecisionType::Scheduled:
    case DecisionType::Removed:
    case DecisionType::Executed: {
      j["kind"] = eventKindName(d.kind);
      j["event_time"] = exactJson(d.eventTime);
      j["sequence"] = d.sequence;
      if (d.kind == EventKind::Input) {
        j["key"] = d.feature;
        j["direction"] = d.b ? "up" : "down";
        break;
      }
      if (d.a != kNoGizmo) j["a"] = replay::gizmoName(names, d.a);
      if (d.b != kNoGizmo) j["b"] = replay::gizmoName(names, d.b);
      if (d.kind == EventKind::Collision) j["feature"] = d.feature;
      if (d.type == DecisionType::Executed) {
        j["event"] = d.eventIndex;
        nlohmann::ordered_json balls = nlohmann::ordered_json::array();
        for (const replay::BallView& b : d.balls)
          balls.push_back({{"ball", b.name},
                           {"x", exactJson(b.x)},
                           {"y", exactJson(b.y)},
                           {"vx_before", exactJson(b.vxBefore)},
                           {"vy_before", exactJson(b.vyBefore)},
                           {"vx_after", exactJson(b.vx)},
                           {"vy_after", exactJson(b.vy)}});
        j["balls"] = balls;
      }
      break;
    }
    case DecisionType::Trigger:
      j["source"] = replay::gizmoName(names, d.gizmo);
      j["target"] = replay::gizmoName(names, d.other);
      break;
    case DecisionType::Action: j["target"] = replay::gizmoName(names, d.gizmo); break;
    case DecisionType::Input:
      j["key"] = d.key;
      j["direction"] = d.direction == KeyDirection::Up ? "up" : "down";
      break;
    case DecisionType::Rule:
      j["rule"] = modelRuleName(d.rule);
      j["gizmo"] = replay::gizmoName(names, d.gizmo);
      if (d.other != kNoGizmo) j["other"] = replay::gizmoName(names, d.other);
      break;
    case DecisionType::Tick:
    case DecisionType::Time: break;
  }
  return j;
}

void printState(const std::string& label, const replay::StateView& s) {
  std::printf("%s: time %s (%.17g), %llu events\n", label.c_str(), s.time.text.c_str(), s.time.value,
              static_cast<unsigned long long>(s.events));
  for (const replay::BallView& b : s.balls)
    std::printf("  %-10s x=%s y=%s vx=%s vy=%s\n             (%.17g, %.17g) v (%.17g, %.17g)\n", b.name.c_str(),
                b.x.text.c_str(), b.y.text.c_str(), b.vx.text.c_str(), b.vy.text.c_str(), b.x.value, b.y.value,
                b.vx.value, b.vy.value);
  if (!s.queue.empty()) {
    std::printf("  queue (%zu events, earliest first):\n", s.queue.size());
    for (const std::string& e : s.queue) std::printf("    %s\n", e.c_str());
  }
}

nlohmann::ordered_json stateJson(const replay::StateView& s) {
  nlohmann::ordered_json balls = nlohmann::ordered_json::array();
  for (const replay::BallView& b : s.balls)
    balls.push_back({{"name", b.name},
                     {"x", exactJson(b.x)},
                     {"y", exactJson(b.y)},
                     {"vx", exactJson(b.vx)},
                     {"vy", exactJson(b.vy)}});
  return {{"time", exactJson(s.time)}, {"events", s.events}, {"balls", balls}, {"queue", s.queue}};
}

bool involves(const DecisionView& d, GizmoId id) {
  switch (d.type) {
    case DecisionType::Scheduled:
    case DecisionType::Removed:
    case DecisionType::Executed: return d.a == id || (d.b == id && d.kind != EventKind::Input);
    case DecisionType::Trigger:
    case DecisionType::Rule: return d.gizmo == id || d.other == id;
    case DecisionType::Action: return d.gizmo == id;
    default: return false;
  }
}

bool hasKind(const DecisionView& d, std::string_view kind) {
  switch (d.type) {
    case DecisionType::Scheduled:
    case DecisionType::Removed:
    case DecisionType::Executed: return eventKindName(d.kind) == kind || replay::decisionTypeName(d.type) == kind;
    case DecisionType::Rule: return kind == "rule" || modelRuleName(d.rule) == kind;
    default: return replay::decisionTypeName(d.type) == kind;
  }
}

bool isKindName(std::string_view kind) {
  for (int k = 0; k < kEventKindCount; ++k)
    if (eventKindName(EventKind(k)) == kind) return true;
  for (int t = 0; t <= int(DecisionType::Time); ++t)
    if (replay::decisionTypeName(DecisionType(t)) == kind) return true;
  for (int r = 0; r < kModelRuleCodeCount; ++r)
    if (!kind.empty() && modelRuleName(ModelRule(r)) == kind) return true;
  return false;
}

bool isLogFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  char magic[replay::kMagic.size()] = {};
  return in.read(magic, sizeof magic) && std::string_view(magic, sizeof magic) == replay::kMagic;
}

std::optional<replay::OpenedLog> openLogFor(const std::string& command, const std::string& path, int& exitCode) {
  try {
    std::optional<replay::OpenedLog> log(replay::openLog(path));
    // A run of a leniently read board must not pass for a run of the original file.
    for (const std::string& w : log->header.boardWarnings)
      std::cerr << "gizmo " << command << ": " << path << ": the board of this run was read leniently: " << w << '\n';
    return log;
  } catch (const std::exception& e) {
    std::cerr << "gizmo " << command << ": " << e.what() << '\n';
    exitCode = kExitBadInput;
    return std::nullopt;
  }
}

int finishWithCutOffLogs(const std::string& command, int code, std::initializer_list<const replay::OpenedLog*> logs,
                         std::initializer_list<std::string> paths) {
  bool cut = false;
  auto path = paths.begin();
  for (const replay::OpenedLog* log : logs) {
    if (!log->reader.truncation().empty()) {
      std::cerr << "gizmo " << command << ": " << *path << ": " << log->reader.truncation() << '\n';
      cut = true;
    }
    ++path;
  }
  return cut && code == kExitOk ? kExitBadInput : code;
}

}  // namespace gizmo::cli
