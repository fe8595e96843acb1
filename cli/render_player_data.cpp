// The replay player's data (render_player_data.hpp): the run's arrays as base64, for run_data.js.
#include "render_player_data.hpp"

#include <array>
#include <map>
#include <stdexcept>

#include "gizmo/core/board/event.hpp"
#include "gizmo/core/board/model_rule.hpp"
#include "render_output.hpp"

namespace gizmo::cli {
namespace {

using Json = nlohmann::ordered_json;

std::int16_t smallId(std::int32_t id) {
  if (id < -1 || id > 32767) throw std::runtime_error("a gizmo id or feature beyond what the player stores (32767)");
  return static_cast<std::int16_t>(id);
}

// Gizmo ids and features fit 16 bits; an input's key code may not, and its Input report (in the
// notes) names it anyway, so an input event's feature is left at −1 here.
Json eventsJson(const RunTrack& t) {
  std::vector<std::int16_t> a, b, feature;
  for (std::int32_t id : t.eventA) a.push_back(smallId(id));
  for (std::int32_t id : t.eventB) b.push_back(smallId(id));
  for (std::size_t i = 0; i < t.eventFeature.size(); ++i)
    feature.push_back(t.eventKind[i] == static_cast<std::uint8_t>(EventKind::Input) ? std::int16_t(-1)
                                                                                    : smallId(t.eventFeature[i]));
  return {{"count", t.eventTime.size()},
          {"time", base64Of(t.eventTime)},
          {"kind", base64Of(t.eventKind)},
          {"a", base64Of(a)},
          {"b", base64Of(b)},
          {"feature", base64Of(feature)}};
}

// Each ball's pieces: the event each follows, position and velocity interleaved (x, y), and an
// index into one shared list of accelerations (there are few: gravity, none, a slope's).
Json ballsJson(const RunTrack& t, Json& accelerations) {
  std::map<std::pair<double, double>, std::uint16_t> index;
  Json balls = Json::array();
  for (const BallTrack& ball : t.balls) {
    std::vector<std::int32_t> event;
    std::vector<double> p, v;
    std::vector<std::uint16_t> a;
    std::vector<std::uint8_t> logged;
    for (const PathPiece& piece : ball.pieces) {
      if (piece.event > 0x7fffffff) throw std::runtime_error("more events than the player stores (2^31)");
      event.push_back(static_cast<std::int32_t>(piece.event));
      p.insert(p.end(), {piece.p.x, piece.p.y});
      v.insert(v.end(), {piece.v.x, piece.v.y});
      const auto key = std::make_pair(piece.a.x, piece.a.y);
      auto it = index.find(key);
      if (it == index.end()) {
        if (index.size() == 65535) throw std::runtime_error("too many distinct accelerations for the player");
        it = index.emplace(key, static_cast<std::uint16_t>(index.size())).first;
        accelerations.push_back(Json::array({piece.a.x, piece.a.y}));
      }
      a.push_back(it->second);
      logged.push_back(piece.logged ? 1 : 0);
    }
    balls.push_back({{"name", ball.name},
                     {"id", ball.id},
                     {"pieces", ball.pieces.size()},
                     {"event", base64Of(event)},
                     {"p", base64Of(p)},
                     {"v", base64Of(v)},
                     {"a", base64Of(a)},
                     {"logged", base64Of(logged)}});
  }
  return balls;
}

// Each flipper's swing anchors: the event each follows (its time is that event's), the progress
// there as a float (a drawing needs no more: 2^-24 of a swing moves the tip by 10^-7 L) and the
// direction.
Json flippersJson(const RunTrack& t) {
  Json flippers = Json::array();
  for (const auto& [id, anchors] : t.flippers) {
    std::vector<std::int32_t> event;
    std::vector<float> s0;
    std::vector<std::int8_t> direction;
    for (const SwingAnchor& s : anchors) {
      event.push_back(static_cast<std::int32_t>(s.event));
      s0.push_back(static_cast<float>(s.s0));
      direction.push_back(static_cast<std::int8_t>(s.direction));
    }
    flippers.push_back({{"id", id},
                        {"anchors", anchors.size()},
                        {"event", base64Of(event)},
                        {"s0", base64Of(s0)},
                        {"direction", base64Of(direction)}});
  }
  return flippers;
}

// The reports of each event, by pattern: a run repeats a few sequences of reports over and over
// (a bumper's hit triggering the same flippers), so the page holds each distinct sequence once
// and, per event, the number of its sequence (0: none).
Json notesJson(const RunTrack& t) {
  using Report = std::array<std::int32_t, 4>;  // type, rule, x, y
  std::map<std::vector<Report>, std::uint32_t> numbers{{{}, 0}};
  Json patterns = Json::array({Json::array()});
  std::vector<std::uint32_t> perEvent(t.eventTime.size(), 0);
  for (std::size_t i = 0; i < t.notes.size();) {
    const std::uint32_t event = t.notes[i].event;
    std::vector<Report> reports;
    for (; i < t.notes.size() && t.notes[i].event == event; ++i)
      reports.push_back({t.notes[i].type, t.notes[i].rule, t.notes[i].x, t.notes[i].y});
    auto [it, added] = numbers.emplace(reports, static_cast<std::uint32_t>(numbers.size()));
    if (added) {
      Json pattern = Json::array();
      for (const Report& r : reports) pattern.push_back(Json::array({r[0], r[1], r[2], r[3]}));
      patterns.push_back(pattern);
    }
    perEvent.at(event) = it->second;
  }
  Json j{{"patterns", patterns}};
  if (numbers.size() <= 65536) {
    j["index_bytes"] = 2;
    j["index"] = base64Of(std::vector<std::uint16_t>(perEvent.begin(), perEvent.end()));
  } else {
    j["index_bytes"] = 4;
    j["index"] = base64Of(perEvent);
  }
  return j;
}

}  // namespace

Json runJson(const PlayerRun& run) {
  const RunTrack& t = run.track;
  Json accelerations = Json::array();
  Json balls = ballsJson(t, accelerations);
  return {{"label", run.label},
          {"model", std::string(motionModelName(t.model))},
          {"precision", t.precision},
          {"duration", t.duration},
          {"start_time", t.startTime},
          {"first_event", t.firstEvent},
          {"end_time", t.endTime},
          {"tolerance", t.tolerance},
          {"truncation", t.truncation},
          {"gizmo_names", t.gizmoNames},
          {"events", eventsJson(t)},
          {"accelerations", accelerations},
          {"balls", balls},
          {"flippers", flippersJson(t)},
          {"notes", notesJson(t)}};
}

Json namesJson() {
  Json kinds = Json::array(), rules = Json::array(), decisions = Json::array();
  for (int k = 0; k < kEventKindCount; ++k) kinds.push_back(std::string(eventKindName(static_cast<EventKind>(k))));
  for (int r = 0; r < kModelRuleCodeCount; ++r)  // a code no rule has: an empty name, never in a log
    rules.push_back(std::string(modelRuleName(static_cast<ModelRule>(r))));
  for (int d = 0; d <= static_cast<int>(replay::DecisionType::Time); ++d)
    decisions.push_back(std::string(replay::decisionTypeName(static_cast<replay::DecisionType>(d))));
  return {{"kinds", kinds}, {"rules", rules}, {"decisions", decisions}};
}

}  // namespace gizmo::cli
