#include "gizmo/verify/engine_trace.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <initializer_list>
#include <map>
#include <nlohmann/json.hpp>
#include <set>

namespace gizmo::verify {
namespace {

using Json = nlohmann::json;

class TraceReader {
 public:
  TraceReader(const std::string& file, const BoardSpec& board, double end) : file_(file), board_(board), end_(end) {
    for (std::size_t i = 0; i < board.balls.size(); ++i) ballIndex_[board.balls[i].name] = i;
    for (const GizmoSpec& g : board.gizmos) gizmos_.insert(g.name);
  }

  EngineTrace read(std::istream& in) {
    std::string text;
    while (std::getline(in, text)) {
      ++line_;
      const Json value = parse(text);
      if (line_ == 1) header(value);
      else step(value);
    }
    if (line_ == 0) fail(0, "the trace is empty: its first line is the header");
    if (trace_.run.record.samples.size() < 2) fail(line_, "the trace has no step after time 0");
    trace_.run.record.steps = trace_.run.record.samples.size() - 1;
    const double last = trace_.run.record.samples.back().time;
    if (last < end_)
      fail(line_, "the trace ends at " + number(last) + " s, before the end of the comparison, " + number(end_) +
                      " s (--time)");
    return std::move(trace_);
  }

 private:
  [[noreturn]] void fail(std::size_t line, const std::string& what) const { throw EngineTraceError(file_, line, what); }

  // The shortest text that reads back as x.
  static std::string number(double x) {
    char text[32];
    const auto [end, error] = std::to_chars(text, text + sizeof text, x);
    return std::string(text, end);
  }

  Json parse(const std::string& text) const {
    if (text.find_first_not_of(" \t\r") == std::string::npos)
      fail(line_, "an empty line (each line is one JSON object)");
    Json value;
    try {
      value = Json::parse(text);
    } catch (const Json::parse_error& e) {
      fail(line_, std::string("not a JSON value: ") + e.what());
    }
    if (!value.is_object()) fail(line_, "not a JSON object (each line is one JSON object)");
    return value;
  }

  // The object's keys must be among `known`, and those in `required` present.
  void keys(const Json& object, const std::string& what, std::initializer_list<const char*> required,
            std::initializer_list<const char*> optional) const {
    for (const char* k : required)
      if (!object.contains(k)) fail(line_, what + " has no \"" + k + "\"");
    // Over the keys alone: a lambda may not capture a structured binding before clang 16.
    for (const auto& item : object.items()) {
      const std::string& k = item.key();
      const auto is = [&](const char* name) { return k == name; };
      if (std::none_of(required.begin(), required.end(), is) && std::none_of(optional.begin(), optional.end(), is))
        fail(line_, what + " has an unknown key \"" + k + "\"");
    }
  }

  double finite(const Json& object, const char* key, const std::string& what) const {
    const Json& v = object.at(key);
    if (!v.is_number()) fail(line_, what + ": \"" + key + "\" is not a number");
    const double x = v.get<double>();
    if (!std::isfinite(x)) fail(line_, what + ": \"" + key + "\" is not a finite number");
    return x;
  }

  std::string text(const Json& object, const char* key, const std::string& what) const {
    const Json& v = object.at(key);
    if (!v.is_string()) fail(line_, what + ": \"" + key + "\" is not a string");
    return v.get<std::string>();
  }

  void header(const Json& h) {
    keys(h, "the header", {"format", "version", "engine", "contacts"}, {"wall_seconds"});
    if (!h.at("format").is_string() || h.at("format").get<std::string>() != kEngineTraceFormat)
      fail(line_, std::string("the header's \"format\" is not \"") + kEngineTraceFormat + "\"");
    if (!h.at("version").is_number_integer() || h.at("version").get<long long>() != kEngineTraceVersion)
      fail(line_, "the header's \"version\" is not " + std::to_string(kEngineTraceVersion) +
                      ", the version this reader knows");
    trace_.engine = text(h, "engine", "the header");
    if (trace_.engine.empty()) fail(line_, "the header's \"engine\" is empty");
    if (!h.at("contacts").is_boolean()) fail(line_, "the header's \"contacts\" is not true or false");
    trace_.run.withCollisions = h.at("contacts").get<bool>();
    if (h.contains("wall_seconds")) {
      const double w = finite(h, "wall_seconds", "the header");
      if (w < 0) fail(line_, "the header's \"wall_seconds\" is negative");
      trace_.run.record.wallSeconds = w;
    }
  }

  void step(const Json& s) {
    if (trace_.run.withCollisions) keys(s, "the step", {"t", "balls"}, {"contacts"});
    else keys(s, "the step", {"t", "balls"}, {});
    TrajectorySample sample;
    sample.time = finite(s, "t", "the step");
    std::vector<TrajectorySample>& samples = trace_.run.record.samples;
    if (samples.empty() && sample.time != 0)
      fail(line_, "the first step's \"t\" is " + number(sample.time) + ", not 0");
    const double previous = samples.empty() ? 0 : samples.back().time;
    if (!samples.empty()) {
      if (sample.time <= previous)
        fail(line_, "\"t\" " + number(sample.time) + " is not after the step before, " + number(previous));
      trace_.run.dt = std::max(trace_.run.dt, sample.time - previous);
    }
    balls(s.at("balls"), sample);
    if (s.contains("contacts")) contacts(s.at("contacts"), previous, sample.time);
    samples.push_back(std::move(sample));
  }

  void balls(const Json& balls, TrajectorySample& sample) const {
    if (!balls.is_object()) fail(line_, "\"balls\" is not an object of the board's balls by name");
    sample.positions.assign(board_.balls.size(), Vec2<double>());
    for (const auto& [name, b] : balls.items()) {
      if (!ballIndex_.contains(name)) fail(line_, "\"balls\" names '" + name + "', which is not a ball of the board");
      const std::string what = "ball '" + name + "'";
      if (!b.is_object()) fail(line_, what + " is not an object");
      keys(b, what, {"x", "y", "vx", "vy"}, {"held"});
      const Vec2<double> p(finite(b, "x", what), finite(b, "y", what)), v(finite(b, "vx", what), finite(b, "vy", what));
      bool held = false;
      if (b.contains("held")) {
        if (!b.at("held").is_boolean()) fail(line_, what + ": \"held\" is not true or false");
        held = b.at("held").get<bool>();
      }
      sample.positions[ballIndex_.at(name)] = p;
      // The core's mechanical energy per unit mass, over free balls (GameBoard::energy).
      if (!held) sample.energy += 0.5 * lengthSquared(v) + board_.gravity * (kBoardSize - p.y);
    }
    for (const BallSpec& b : board_.balls)
      if (!balls.contains(b.name))
        fail(line_, "\"balls\" has no ball '" + b.name + "' (every ball of the board, each step)");
  }

  void contacts(const Json& list, double from, double to) {
    if (!list.is_array()) fail(line_, "\"contacts\" is not an array");
    for (const Json& c : list) {
      const std::string what = "a contact";
      if (!c.is_object()) fail(line_, what + " is not an object");
      keys(c, what, {"t", "ball", "other", "x", "y"}, {});
      const double t = finite(c, "t", what);
      if (t < from || t > to)
        fail(line_,
             "a contact at " + number(t) + " s lies outside its step, " + number(from) + " to " + number(to) + " s");
      std::vector<CollisionRecord>& hits = trace_.run.record.collisions;
      if (!hits.empty() && t < hits.back().time)
        fail(line_, "a contact at " + number(t) + " s comes before the one listed before it, at " +
                        number(hits.back().time) + " s");
      const std::string ball = text(c, "ball", what), other = text(c, "other", what);
      if (!ballIndex_.contains(ball))
        fail(line_, "a contact names '" + ball + "' as its ball, which is not a ball of the board");
      const bool otherIsBall = ballIndex_.contains(other);
      if (other == ball) fail(line_, "a contact of ball '" + ball + "' with itself");
      // Its position is `ball`'s centre; of two balls, the report names the one that sorts first.
      if (otherIsBall && other < ball)
        fail(line_, "a contact of two balls names '" + ball + "' as its ball: name '" + other +
                        "', whose name sorts first, and give its centre");
      if (!otherIsBall && !gizmos_.contains(other) && other != kOuterWallsName)
        fail(line_, "a contact names '" + other + "', which is not a gizmo, a ball or " + kOuterWallsName);
      CollisionRecord hit = collisionRecord(t, ball, other, otherIsBall);
      hit.position = Vec2<double>(finite(c, "x", what), finite(c, "y", what));
      hits.push_back(std::move(hit));
    }
  }

  const std::string& file_;
  const BoardSpec& board_;
  double end_;
  std::map<std::string, std::size_t> ballIndex_;
  std::set<std::string> gizmos_;
  std::size_t line_ = 0;
  EngineTrace trace_;
};

}  // namespace

EngineTrace readEngineTrace(std::istream& in, const std::string& file, const BoardSpec& board, double end) {
  return TraceReader(file, board, end).read(in);
}

EngineTrace readEngineTraceFile(const std::string& path, const BoardSpec& board, double end) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw EngineTraceError(path, 0, "cannot read the file");
  return readEngineTrace(in, path, board, end);
}

}  // namespace gizmo::verify
