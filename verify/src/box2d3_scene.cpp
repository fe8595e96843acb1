// The scene that verify/box2d3/run_scene.mjs builds in Box2D v3: the bodies of the one mapping
// (box2d_mapping.cpp) written out as they are, so that no second copy of it exists, in the order
// the driver numbers them (box2d_engine.hpp).
#include <nlohmann/json.hpp>

#include "gizmo/core/board/physics_params.hpp"
#include "gizmo/verify/box2d3_run.hpp"
#include "gizmo/verify/box2d_mapping.hpp"

namespace gizmo::verify {
namespace {

using Json = nlohmann::ordered_json;

Json point(const Vec2<double>& p) { return Json::array({p.x, p.y}); }

Json partJson(const Box2dPart& part) {
  Json points = Json::array();
  for (const Vec2<double>& p : part.points) points.push_back(point(p));
  switch (part.kind) {
    case Box2dPart::Kind::Polygon: return {{"kind", "polygon"}, {"points", points}, {"radius", part.radius}};
    case Box2dPart::Kind::Edge: return {{"kind", "edge"}, {"points", points}, {"radius", part.radius}};
    case Box2dPart::Kind::Circle: break;
  }
  return {{"kind", "circle"}, {"centre", point(part.centre)}, {"radius", part.radius}};
}

Json bodyJson(const Box2dBody& body) {
  Json parts = Json::array();
  for (const Box2dPart& part : body.parts) parts.push_back(partJson(part));
  return {{"name", body.name},
          {"kinematic", body.kinematic},
          {"sensor", body.sensor},
          {"restitution", body.restitution},
          {"origin", point(body.origin)},
          {"angle", body.angle},
          {"parts", parts}};
}

}  // namespace

std::optional<std::string> box2d3CannotModel(const BoardSpec& board) { return box2dCannotModel(board); }

std::string box2d3Scene(const RunRequest& request, const Box2dOptions& options, const std::string& traceOut) {
  Json bodies = Json::array({bodyJson(box2dOuterWalls())});
  for (const GizmoSpec& g : request.board.gizmos) bodies.push_back(bodyJson(box2dBodyOf(g)));
  Json balls = Json::array();
  for (const BallSpec& b : request.board.balls)
    balls.push_back({{"name", b.name}, {"x", b.x}, {"y", b.y}, {"vx", b.vx}, {"vy", b.vy}, {"radius", kBallRadius}});
  const Json scene{{"format", "gizmo-box2d-scene"},
                   {"version", 3},
                   {"gravity", request.board.gravity},
                   {"rest_speed", PhysicsParams<double>{}.restSpeed},
                   {"dt", options.dt},
                   {"sub_steps", kBox2d3SubSteps},
                   {"bullets", options.bullet},
                   {"continuous", options.continuous},
                   {"restitution_threshold", options.restitutionThreshold},
                   {"bodies", bodies},
                   {"balls", balls},
                   {"trace_out", traceOut.empty() ? Json(nullptr) : Json(traceOut)}};
  return scene.dump();
}

}  // namespace gizmo::verify
