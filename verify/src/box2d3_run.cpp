// Box2D v3 as the driver's engine (box2d_engine.hpp): verify/box2d3/run_scene.mjs under node,
// told the scene, then asked for one step at a time over a pipe (line_process.hpp).
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

#include "box2d_driver.hpp"
#include "gizmo/verify/box2d3_run.hpp"
#include "line_process.hpp"

namespace gizmo::verify {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

fs::path programDir() {
  if (const char* dir = std::getenv("GIZMO_BOX2D3_DIR"); dir != nullptr && *dir != '\0') return dir;
  return GIZMO_BOX2D3_SOURCE_DIR;
}

bool nodeOnPath() {
  const char* path = std::getenv("PATH");
  if (path == nullptr) return false;
  std::stringstream dirs(path);
  for (std::string dir; std::getline(dirs, dir, ':');)
    if (!dir.empty() && ::access((fs::path(dir) / "node").c_str(), X_OK) == 0) return true;
  return false;
}

class Box2d3Engine final : public SteppedEngine {
 public:
  Box2d3Engine(const RunRequest& request, const Box2dOptions& options, const std::string& traceOut)
      : process_({"node", (programDir() / "run_scene.mjs").string()}, "the Box2D v3 program (node run_scene.mjs)"),
        bodyCount_(1 + request.board.gizmos.size()),
        balls_(request.board.balls.size()) {
    process_.send(box2d3Scene(request, options, traceOut));
    const Json ready = reply();
    if (!ready.contains("engine") || !ready.at("engine").is_string()) bad("its first reply names no engine");
    name_ = ready.at("engine").get<std::string>();
    readState(ready);
  }

  const std::string& name() const { return name_; }

  // The run is over: the program writes the rest of its trace, if it keeps one, and ends. The
  // requests made after the last step go with it: a hold among them marks a capture in it.
  void end(std::uint64_t steps) {
    process_.send(Json{{"end", true}, {"ops", std::move(ops_)}}.dump());
    ops_ = Json::array();
    const Json r = reply();
    if (!r.contains("steps") || !r.at("steps").is_number_unsigned() || r.at("steps").get<std::uint64_t>() != steps)
      bad("its last reply does not say it took the " + std::to_string(steps) + " steps asked for");
    if (process_.finish() != 0) bad("it did not end with exit code 0");
  }

  EngineBall ball(std::size_t i) const override { return balls_.at(i); }

  double angle(std::size_t body) const override {
    const auto it = angles_.find(body);
    if (it == angles_.end()) bad("it gave no angle of body " + std::to_string(body));
    return it->second;
  }

  // Sent with the step, once its length is known (step()).
  void turn(std::size_t body, double radians) override { turns_.emplace_back(body, radians); }

  void setVelocity(std::size_t i, const Vec2<double>& v) override {
    balls_.at(i).velocity = v;
    ops_.push_back(Json::array({"v", i, v.x, v.y}));
  }

  void hold(std::size_t i, const Vec2<double>& p) override {
    balls_.at(i) = EngineBall{p, Vec2<double>(), true};
    ops_.push_back(Json::array({"hold", i, p.x, p.y}));
  }

  void release(std::size_t i, const Vec2<double>& p, const Vec2<double>& v) override {
    balls_.at(i) = EngineBall{p, v, false};
    ops_.push_back(Json::array({"release", i, p.x, p.y, v.x, v.y}));
  }

  EngineStep step(double t0, double dt) override {
    EngineStep out;
    // v3 turns a body by atan(h ω) a sub-step of h (b2IntegrateRotation): the rate that turns it
    // by `radians` over a step's n sub-steps is n tan(radians / n) / dt.
    const double n = kBox2d3SubSteps;
    for (const auto& [body, radians] : turns_) {
      const double omega = n * std::tan(radians / n) / dt;
      out.rotationCapped = out.rotationCapped || std::fabs(omega * dt) > kBox2d3MaxRotation * (1 + 1e-5);
      ops_.push_back(Json::array({"turn", body, omega}));
    }
    turns_.clear();
    for (const EngineBall& b : balls_)
      out.speedCapped = out.speedCapped || (!b.held && length(b.velocity) > kBox2d3MaxSpeed);
    process_.send(Json{{"t0", t0}, {"ops", std::move(ops_)}}.dump());
    ops_ = Json::array();
    const Json r = reply();
    readState(r);
    if (!r.contains("contacts") || !r.at("contacts").is_array()) bad("a reply has no contacts");
    for (const Json& c : r.at("contacts")) {
      if (!c.is_array() || c.size() != 7) bad("a contact is not [kind, ball, other is a ball, other, t, x, y]");
      out.contacts.push_back(contactOf(c));
    }
    return out;
  }

 private:
  [[noreturn]] static void bad(const std::string& what) {
    throw std::runtime_error("the Box2D v3 program's reply: " + what);
  }

  EngineContact contactOf(const Json& c) const {
    try {
      const std::string kind = c[0].get<std::string>();
      EngineContact contact;
      contact.kind = kind == "hit"     ? EngineContact::Kind::Hit
                     : kind == "enter" ? EngineContact::Kind::Enter
                                       : EngineContact::Kind::Exit;
      contact.ball = c[1].get<std::size_t>();
      contact.otherIsBall = c[2].get<int>() != 0;
      contact.other = c[3].get<std::size_t>();
      contact.time = c[4].get<double>();
      contact.position = Vec2<double>(c[5].get<double>(), c[6].get<double>());
      if (contact.ball >= balls_.size() || contact.other >= (contact.otherIsBall ? balls_.size() : bodyCount_))
        bad("a contact names a ball or a body the board does not have");
      return contact;
    } catch (const Json::exception& e) {
      bad(std::string("a contact does not read: ") + e.what());
    }
  }

  Json reply() {
    const std::string line = process_.receive();
    try {
      return Json::parse(line);
    } catch (const Json::exception& e) {
      bad(std::string("not JSON: ") + e.what());
    }
  }

  void readState(const Json& r) {
    try {
      const Json& balls = r.at("balls");
      if (balls.size() != balls_.size())
        bad("it has " + std::to_string(balls.size()) + " balls, the board " + std::to_string(balls_.size()));
      for (std::size_t i = 0; i < balls_.size(); ++i) {
        const Json& b = balls[i];
        balls_[i] = EngineBall{Vec2<double>(b.at(0).get<double>(), b.at(1).get<double>()),
                               Vec2<double>(b.at(2).get<double>(), b.at(3).get<double>()), b.at(4).get<int>() != 0};
      }
      for (const Json& a : r.at("angles")) angles_[a.at(0).get<std::size_t>()] = a.at(1).get<double>();
    } catch (const Json::exception& e) {
      bad(std::string("the balls or the angles do not read: ") + e.what());
    }
  }

  LineProcess process_;
  std::size_t bodyCount_;  // the walls and the gizmos
  std::string name_;
  std::vector<EngineBall> balls_;
  std::map<std::size_t, double> angles_;  // kinematic bodies
  std::vector<std::pair<std::size_t, double>> turns_;
  Json ops_ = Json::array();
};

}  // namespace

std::optional<std::string> box2d3Unavailable() {
  if (!nodeOnPath()) return std::string("Box2D v3 runs under node, and there is no node on the PATH");
  const fs::path dir = programDir();
  if (!fs::exists(dir / "run_scene.mjs")) return "there is no run_scene.mjs in " + dir.string();
  if (!fs::exists(dir / "node_modules" / "box2d3-wasm" / "package.json"))
    return "the box2d3-wasm package is not installed in " + dir.string() + " (scripts/setup.sh installs it)";
  return std::nullopt;
}

EngineTrace runBox2d3(const RunRequest& request, const Box2dOptions& options, const std::string& traceOut) {
  if (const std::optional<std::string> why = box2d3Unavailable()) throw std::runtime_error(*why);
  // The program's working folder is ours, but a path it is handed should not depend on it.
  Box2d3Engine engine(request, options, traceOut.empty() ? traceOut : fs::absolute(traceOut).string());
  EngineTrace out;
  out.engine = engine.name();
  out.run.record = driveBox2dRun(request, options.dt, engine);
  engine.end(out.run.record.steps);
  out.run.dt = options.dt;
  out.run.withCollisions = true;
  return out;
}

}  // namespace gizmo::verify
