// Reading and writing path files (see render_path_file.hpp for the layout).
#include "render_path_file.hpp"

#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <span>
#include <sstream>

#include "gizmo/io/board_writer.hpp"
#include "gizmo/replay/checksum.hpp"

namespace gizmo::cli {
namespace {

std::uint64_t checksumOf(const std::string& text) {
  return replay::checksum64(std::span(reinterpret_cast<const std::uint8_t*>(text.data()), text.size()));
}

// %.17g keeps a double's every bit; Box2D's positions are floats, which %.9g already keeps.
std::string number(double x, int digits) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.*g", digits, x);
  return buf;
}

std::vector<std::string> fields(const std::string& line) {
  std::vector<std::string> out;
  std::istringstream in(line);
  for (std::string f; in >> f;) out.push_back(f);
  return out;
}

// Reads the file line by line and says where anything is wrong.
class LineReader {
 public:
  explicit LineReader(const std::string& path) : path_(path), in_(path, std::ios::binary) {
    if (!in_) throw PathFileError(path + ": cannot read the file");
  }

  // The next line without its line end; false at the end of the file.
  bool next(std::string& line) {
    if (!std::getline(in_, line)) return false;
    ++number_;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    return true;
  }
  std::string expect(const std::string& what) {
    std::string line;
    if (!next(line)) fail("the file stops before its " + what + " line (cut off?)", number_ + 1);
    return line;
  }
  std::size_t line() const { return number_; }
  [[noreturn]] void fail(const std::string& message) const { fail(message, number_); }
  [[noreturn]] void fail(const std::string& message, std::size_t line) const {
    throw PathFileError(path_ + ":" + std::to_string(line) + ": " + message);
  }

  double finite(const std::string& text, const std::string& what) const {
    char* end = nullptr;
    const double x = std::strtod(text.c_str(), &end);
    if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(x))
      fail(what + " '" + text + "' is not a finite number");
    return x;
  }
  std::uint64_t checksum(const std::string& text, const std::string& what) const {
    char* end = nullptr;
    const unsigned long long x = std::strtoull(text.c_str(), &end, 16);
    if (text.size() != 16 || end != text.c_str() + text.size()) fail(what + " '" + text + "' is not 16 hex digits");
    return x;
  }

  // "KEY rest-of-line": the rest, after checking the key.
  std::string keyed(const std::string& key) {
    const std::string line = expect("'" + key + "'");
    if (line.compare(0, key.size() + 1, key + " ") != 0 || line.size() == key.size() + 1)
      fail("expected '" + key + " …', found '" + line.substr(0, 60) + "'");
    return line.substr(key.size() + 1);
  }

 private:
  std::string path_;
  std::ifstream in_;
  std::size_t number_ = 0;
};

}  // namespace

std::string checksumText(std::uint64_t checksum) {
  char buf[24];
  std::snprintf(buf, sizeof buf, "%016" PRIx64, checksum);
  return buf;
}

std::uint64_t boardChecksum(const BoardSpec& board) { return checksumOf(io::writeTextBoard(board)); }

std::uint64_t keysChecksum(const std::vector<TimedKey>& keys) {
  std::string text;
  for (const TimedKey& k : keys) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%a %s %d\n", k.time, k.direction == KeyDirection::Up ? "up" : "down", k.key);
    text += buf;
  }
  return checksumOf(text);
}

bool isPathFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  const std::string magic = kPathFileMagic;
  std::string start(magic.size(), '\0');
  return in.read(start.data(), static_cast<std::streamsize>(start.size())) && start == magic;
}

std::string pathFileText(const PathFile& f) {
  std::string out;
  out += std::string(kPathFileMagic) + "\n";
  out += "engine " + f.engine + "\n";
  out += "board " + checksumText(f.boardChecksum) + " " + f.boardName + "\n";
  out += "keys " + checksumText(f.keysChecksum) + "\n";
  out += "model " + std::string(motionModelName(f.model)) + "\n";
  out += "dt " + number(f.dt, 17) + "\n";
  out += "time " + number(f.duration, 17) + "\n";
  out += "balls";
  for (const std::string& b : f.balls) out += " " + b;
  out += "\nsamples\n";
  // Step by step, every ball in turn: the order a reader of the text expects.
  std::size_t longest = 0;
  for (const auto& s : f.samples) longest = std::max(longest, s.size());
  for (std::size_t k = 0; k < longest; ++k)
    for (std::size_t b = 0; b < f.balls.size(); ++b) {
      if (k >= f.samples[b].size()) continue;
      const PathSample& s = f.samples[b][k];
      out += number(s.t, 17) + " " + f.balls[b] + " " + number(s.p.x, 9) + " " + number(s.p.y, 9) + "\n";
    }
  out += "end\n";
  return out;
}

PathFile readPathFile(const std::string& path) {
  LineReader in(path);
  PathFile f;
  if (in.expect("'gizmo-path 1'") != kPathFileMagic)
    in.fail("not a path file (its first line must be '" + std::string(kPathFileMagic) + "')");
  f.engine = in.keyed("engine");
  {
    const std::string board = in.keyed("board");
    const std::size_t space = board.find(' ');
    f.boardChecksum = in.checksum(board.substr(0, space), "the board checksum");
    f.boardName = space == std::string::npos ? "" : board.substr(space + 1);
  }
  f.keysChecksum = in.checksum(in.keyed("keys"), "the keys checksum");
  {
    const std::string model = in.keyed("model");
    if (model == "ballistic") f.model = MotionModel::Ballistic;
    else if (model == "classic") f.model = MotionModel::Classic;
    else in.fail("the model '" + model + "' is neither ballistic nor classic");
  }
  f.dt = in.finite(in.keyed("dt"), "the step size");
  if (!(f.dt > 0)) in.fail("the step size must be positive");
  f.duration = in.finite(in.keyed("time"), "the time");
  if (f.duration < 0) in.fail("the time must not be negative");
  std::map<std::string, std::size_t> index;
  for (const std::string& name : fields(in.keyed("balls"))) {
    if (!index.emplace(name, f.balls.size()).second) in.fail("ball '" + name + "' is listed twice");
    f.balls.push_back(name);
  }
  f.samples.resize(f.balls.size());
  if (in.expect("'samples'") != "samples") in.fail("expected 'samples'");
  std::string line;
  bool ended = false;
  while (in.next(line)) {
    if (line == "end") {
      ended = true;
      break;
    }
    const std::vector<std::string> parts = fields(line);
    if (parts.size() != 4) in.fail("a sample is 'TIME BALL X Y', found '" + line.substr(0, 60) + "'");
    const auto ball = index.find(parts[1]);
    if (ball == index.end()) in.fail("ball '" + parts[1] + "' is not in the 'balls' line");
    PathSample s;
    s.t = in.finite(parts[0], "the time");
    s.p = Vec2<double>(in.finite(parts[2], "x"), in.finite(parts[3], "y"));
    std::vector<PathSample>& list = f.samples[ball->second];
    if (!list.empty() && !(s.t > list.back().t))
      in.fail("ball " + parts[1] + "'s times must increase (" + parts[0] + " after " + number(list.back().t, 17) + ")");
    list.push_back(s);
  }
  if (!ended) in.fail("the file stops before its 'end' line (cut off?)", in.line() + 1);
  if (in.next(line)) in.fail("text after the 'end' line");
  for (std::size_t b = 0; b < f.balls.size(); ++b)
    if (f.samples[b].empty()) in.fail("ball " + f.balls[b] + " has no sample");
  return f;
}

PathFile box2dPathFile(const RunRequest& request, const std::string& boardName, const verify::Box2dOptions& options,
                       const std::vector<verify::TrajectorySample>& samples) {
  PathFile f;
  char engine[160];
  std::snprintf(engine, sizeof engine,
                "Box2D %s, bullets %s, restitution threshold %g m/s, %d velocity / %d position iterations",
                verify::box2dVersion().c_str(), options.bullet ? "on" : "off", options.restitutionThreshold,
                options.velocityIterations, options.positionIterations);
  f.engine = engine;
  f.boardChecksum = boardChecksum(request.board);
  f.boardName = boardName;
  f.keysChecksum = keysChecksum(request.keys);
  f.model = request.model;
  f.dt = options.dt;
  f.duration = request.duration;
  for (const BallSpec& b : request.board.balls) f.balls.push_back(b.name);
  f.samples.resize(f.balls.size());
  // Box2D's steps end at k·dt; the last one kept is the one that reaches the run's end.
  const double last = std::ceil(request.duration / options.dt - 1e-9) * options.dt;
  for (const verify::TrajectorySample& s : samples) {
    if (s.time > last * (1 + 1e-12)) break;
    for (std::size_t b = 0; b < f.balls.size() && b < s.positions.size(); ++b)
      f.samples[b].push_back(PathSample{s.time, s.positions[b]});
  }
  return f;
}

}  // namespace gizmo::cli
