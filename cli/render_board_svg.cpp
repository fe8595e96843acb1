// The board picture (see render_board_svg.hpp). Coordinates are board units (L), y down, as in
// the simulator; the picture is 40 pixels per L.
#include "render_board_svg.hpp"

#include <cmath>
#include <cstdio>
#include <set>

#include "kinds/drawing_registry.hpp"

namespace gizmo::cli {
namespace {

constexpr double kPixelsPerUnit = 40;

// A coordinate to a ten-thousandth of L: far below a pixel, and it keeps long paths short.
std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4f", v);
  std::string s = buf;
  while (!s.empty() && s.back() == '0') s.pop_back();
  if (!s.empty() && s.back() == '.') s.pop_back();
  return s == "-0" ? "0" : s;
}

std::string pt(const Vec2<double>& p) { return num(p.x) + "," + num(p.y); }

std::string escapeXml(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '<') out += "&lt;";
    else if (c == '>') out += "&gt;";
    else if (c == '&') out += "&amp;";
    else if (c == '"') out += "&quot;";
    else out += c;
  }
  return out;
}

Vec2<double> quarter(int q) {
  switch (((q % 4) + 4) % 4) {
    case 0: return {1, 0};
    case 1: return {0, 1};
    case 2: return {-1, 0};
    default: return {0, -1};
  }
}

// One rule per class of the kinds' figures, in the kind list's order, each in its kind's colour.
std::string kindStyles() {
  std::string rules;
  std::set<std::string_view> written;
  forEachKind([&]<GizmoType T>(KindTag<T>) {
    using Drawing = KindDrawing<T>;
    if (!written.insert(Drawing::svgClass).second) return;
    const std::string colour(Drawing::colour);
    rules += "." + std::string(Drawing::svgClass) + "{";
    switch (Drawing::figure) {
      case Figure::Polygon:
      case Figure::Disc: rules += "fill:" + colour; break;
      case Figure::Flipper:
      case Figure::Cross: rules += "stroke:" + colour + ";stroke-linecap:round"; break;
      case Figure::CellOutline:
        rules += "fill:none;stroke:" + colour + ";stroke-width:0.06;stroke-dasharray:0.15 0.1";
        break;
    }
    rules += "}";
  });
  return rules;
}

std::string gizmoSvg(const GizmoDrawing& g) {
  const std::string title = "<title>" + escapeXml(g.name) + "</title>";
  switch (figureOf(g.type)) {  // each kind's drawing file says (cli/kinds/STEM.hpp)
    case Figure::Disc:
      return std::string("<circle class=\"") + svgClassOf(g.type) + "\" cx=\"" + num(g.centre.x) + "\" cy=\"" +
             num(g.centre.y) + "\" r=\"" + num(g.radius) + "\">" + title + "</circle>\n";
    case Figure::Flipper: {
      const Vec2<double> tip = g.pivot + g.length * quarter(g.restQuarter);
      return std::string("<line class=\"") + svgClassOf(g.type) + "\" stroke-width=\"" + num(2 * g.radius) +
             "\" x1=\"" + num(g.pivot.x) + "\" y1=\"" + num(g.pivot.y) + "\" x2=\"" + num(tip.x) + "\" y2=\"" +
             num(tip.y) + "\">" + title + "</line>\n";
    }
    case Figure::Cross: {
      // The cross at rest: two bars through the centre (a picture of the board, not of a moment).
      std::string bars;
      for (int q = 0; q < 2; ++q) {
        const Vec2<double> a = g.centre - g.length * quarter(q), b = g.centre + g.length * quarter(q);
        bars += std::string("<line class=\"") + svgClassOf(g.type) + "\" stroke-width=\"" + num(2 * g.radius) +
                "\" x1=\"" + num(a.x) + "\" y1=\"" + num(a.y) + "\" x2=\"" + num(b.x) + "\" y2=\"" + num(b.y) + "\">" +
                title + "</line>\n";
      }
      return bars;
    }
    case Figure::Polygon:
    case Figure::CellOutline: {
      std::string points;
      for (const Vec2<double>& p : g.polygon) points += (points.empty() ? "" : " ") + pt(p);
      return std::string("<polygon class=\"") + svgClassOf(g.type) + "\" points=\"" + points + "\">" + title +
             "</polygon>\n";
    }
  }
  return {};  // not reached: every figure is a case
}

// One ball's path: each piece is a parabola (or a line), which a quadratic Bézier draws exactly:
// its control point is where the tangents at the two ends meet, p0 + v0·(t1 − t0)/2.
std::string pathSvg(const BallTrack& ball, double endTime) {
  std::string d;
  Vec2<double> pen(NAN, NAN);
  for (std::size_t i = 0; i < ball.pieces.size(); ++i) {
    const PathPiece& piece = ball.pieces[i];
    const double end = i + 1 < ball.pieces.size() ? ball.pieces[i + 1].t0 : endTime;
    const Vec2<double> from = piece.p, to = positionAt(piece, end);
    if (!(pen == from)) d += "M" + pt(from);
    if (end > piece.t0 && !(from == to)) d += "Q" + pt(from + (0.5 * (end - piece.t0)) * piece.v) + " " + pt(to);
    pen = to;
  }
  if (d.empty()) return "";
  return "<path class=\"trace\" d=\"" + d + "\"><title>" + escapeXml(ball.name) + "</title></path>\n";
}

// A mark at each collision point; points closer than a hundredth of the ball's size (one grid
// cell of the picture's marks) are the same mark, which keeps a ball that jitters between two
// bumpers from filling the picture with a million circles.
std::string collisionsSvg(const RunTrack& run) {
  constexpr double kCell = 0.02;
  std::set<std::pair<long long, long long>> marked;
  std::string out;
  for (const Vec2<double>& p : run.collisionPoints) {
    if (!marked.emplace(std::llround(p.x / kCell), std::llround(p.y / kCell)).second) continue;
    out += "<circle class=\"hit\" cx=\"" + num(p.x) + "\" cy=\"" + num(p.y) + "\" r=\"0.08\"/>\n";
  }
  return out;
}

}  // namespace

std::string boardSvg(const BoardDrawing& board, const RunTrack* trace) {
  const double margin = 0.25, side = board.size + 2 * margin;
  std::string svg = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + num(side * kPixelsPerUnit) + "\" height=\"" +
                    num(side * kPixelsPerUnit) + "\" viewBox=\"" + num(-margin) + " " + num(-margin) + " " + num(side) +
                    " " + num(side) + "\">\n";
  svg += "<style>.wall{fill:#10131a;stroke:#8a93a6;stroke-width:0.06}" + kindStyles() +
         ".ball{fill:#f4f4f4;stroke:#222;stroke-width:0.03}.trace{fill:none;stroke:#ffd54a;stroke-width:0.04;"
         "stroke-linejoin:round;opacity:0.8}.hit{fill:#ff4040}</style>\n";
  svg +=
      "<rect class=\"wall\" x=\"0\" y=\"0\" width=\"" + num(board.size) + "\" height=\"" + num(board.size) + "\"/>\n";
  for (const GizmoDrawing& g : board.gizmos) svg += gizmoSvg(g);
  if (trace) {
    for (const BallTrack& ball : trace->balls) svg += pathSvg(ball, trace->endTime);
    svg += collisionsSvg(*trace);
  }
  for (const BallSpec& b : board.balls)
    svg += "<circle class=\"ball\" cx=\"" + num(b.x) + "\" cy=\"" + num(b.y) + "\" r=\"" + num(board.ballRadius) +
           "\"><title>" + escapeXml(b.name) + "</title></circle>\n";
  svg += "</svg>\n";
  return svg;
}

}  // namespace gizmo::cli
