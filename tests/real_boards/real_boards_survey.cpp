// Loads every board file of the real-board collection (../shared/boards/real, read where it lies)
// and checks each against its kind (board_kinds.hpp):
// - boards their programs saved (S), written by hand (H) or as valid test fixtures (T) load; each
//   then runs 60 s of board time in the ballistic model (and the classic one, up to 64 balls)
//   without stalling, every
//   ball still on the board, and the canonical text writer's copy of it reads back with no warning
//   as the same board (so it runs the same decisions); and the board as given and three
//   variations of it (`gizmo fuzz BOARD`, 3 s each) hold every property of docs/fuzzing.md;
// - boards malformed on purpose (M) are refused at a position, or at least never read silently:
//   what is read leniently is a warning with a position, which --strict refuses;
// - files of other formats are refused with a message that says what they look like;
// - every refusal is located (a line, or a whole-file "this looks like" message).
//
//   real_boards_survey DIR --unlisted FILE [--shard K/N] [--table FILE]
// --unlisted names tests/real_boards/unlisted.tsv (the kinds SOURCES.md does not give); --table
// writes the per-file table of docs/board-files.md (scripts/board-files-table).
// A clone on its own has no collection beside it: then the survey says so and exits 77, which
// ctest counts as skipped, except in CI (CI=true), whose copy of shared/ must hold it.
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "board_kinds.hpp"
#include "gizmo/core/board/game_board.hpp"
#include "gizmo/core/run/run.hpp"
#include "gizmo/io/board_file.hpp"
#include "gizmo/io/board_writer.hpp"
#include "gizmo/io/text_reader.hpp"
#include "gizmo/verify/fuzz/campaign.hpp"

namespace fs = std::filesystem;

// The exit code that ctest's SKIP_RETURN_CODE counts as a skipped test (tests/real_boards/CMakeLists.txt).
constexpr int kSkipped = 77;
using namespace gizmo;
using realboards::BoardKind;

namespace {

struct Outcome {
  bool loaded = false;
  io::ReadResult read;                  // when loaded
  std::vector<io::Diagnostic> refusal;  // when refused
  std::vector<std::string> failures;    // broken expectations
};

bool located(const std::vector<io::Diagnostic>& ds) {
  for (const io::Diagnostic& d : ds)
    if (d.line <= 0 && d.message.find("this looks like") == std::string::npos &&
        d.message.find(" more error") == std::string::npos)
      return false;
  return !ds.empty();
}

bool ballsOnBoard(const RunSummary& s) {
  for (const BallState& b : s.balls)
    if (!(b.x >= 0 && b.x <= kBoardSize && b.y >= 0 && b.y <= kBoardSize)) return false;
  return true;
}

// The classic model's cost grows fast with the ball count: on a loaded two-core machine the board of
// 343 balls took over 120 s for 60 s of board time (9 s ballistic), so classic runs only on boards
// of at most this many balls (all but the two largest of the collection).
constexpr std::size_t kClassicMaxBalls = 64;

void runs(const BoardSpec& board, Outcome& out) {
  for (const MotionModel model : {MotionModel::Ballistic, MotionModel::Classic}) {
    if (model == MotionModel::Classic && board.balls.size() > kClassicMaxBalls) continue;
    RunRequest request;
    request.board = board;
    request.model = model;
    request.duration = 60;
    const char* name = model == MotionModel::Ballistic ? "ballistic" : "classic";
    try {
      const RunSummary s = simulate<double>(request);
      // Spawners add balls as the board runs; none is ever taken off the list.
      if (s.balls.size() < board.balls.size())
        out.failures.push_back(std::string("after 60 s (") + name + ") the board has lost a ball");
      if (!ballsOnBoard(s)) out.failures.push_back(std::string("after 60 s (") + name + ") a ball is off the board");
    } catch (const StallError& e) {
      out.failures.push_back(std::string("the run stalled (") + name + "): " + e.what());
    }
  }
}

// The board as given and three variations of it, 3 s each, under every property: what
// `gizmo fuzz BOARD --time 3 --count 4 --seed 43` checks.
void variationsHold(const BoardSpec& board, Outcome& out) {
  namespace fz = gizmo::verify::fuzz;
  RunRequest base;
  base.board = board;
  base.duration = 3;
  const fz::VariationSource source(base, fz::VariationOptions{});
  fz::CampaignOptions c;
  for (const fz::Property& p : fz::allProperties()) c.properties.push_back(&p);
  c.source = &source;
  c.count = 4;
  c.seed = 43;
  c.shrinkBudget = 0;
  for (const fz::CaseOutcome& o : fz::runCampaign(c).outcomes)
    if (!o.holds) out.failures.push_back("variation " + std::to_string(o.index) + ": " + o.property + ": " + o.message);
}

void writtenBackIsTheSame(const BoardSpec& board, Outcome& out) {
  try {
    const io::ReadResult again = io::readTextBoard(io::writeTextBoard(board), "written.txt");
    io::refuseLeniency(again);
    if (io::writeXmlBoard(again.board) != io::writeXmlBoard(board))
      out.failures.push_back("the canonical text of the board reads back as another board");
  } catch (const io::InputError& e) {
    out.failures.push_back(std::string("the canonical text of the board does not read strictly: ") + e.what());
  }
}

Outcome survey(const fs::path& file, const BoardKind& kind) {
  Outcome out;
  try {
    out.read = io::readBoardFile(file.string());
    out.loaded = true;
  } catch (const io::InputError& e) {
    out.refusal = e.diagnostics();
  }
  if (!out.loaded && !located(out.refusal)) out.failures.push_back("refused without a position");
  if (!realboards::isBoardFormat(kind)) {
    if (out.loaded || out.refusal.front().message.find("this looks like") == std::string::npos)
      out.failures.push_back("a file of another format is not refused as such");
    return out;
  }
  switch (kind.kind) {
    case 'S':
    case 'H':
    case 'T':
      if (!out.loaded) {
        out.failures.push_back("does not load");
        break;
      }
      writtenBackIsTheSame(out.read.board, out);
      runs(out.read.board, out);
      variationsHold(out.read.board, out);
      break;
    case 'M':
      if (out.loaded && out.read.warnings.empty()) out.failures.push_back("a malformed board loads without a warning");
      if (out.loaded && !located(out.read.warnings)) out.failures.push_back("a warning has no position");
      break;
    default: break;  // B: whatever happens, without a crash
  }
  return out;
}

// "warning text" → its kind of leniency, short, for the table: the message up to its first ';'.
std::string brief(const io::Diagnostic& d) {
  std::string m = d.message;
  const std::size_t cut = std::min(m.find(';'), m.find(" (and "));
  if (cut != std::string::npos) m = m.substr(0, cut);
  if (m.size() > 90) m = m.substr(0, 87) + "...";
  for (char& c : m)
    if (c == '|') c = '/';
  return "line " + std::to_string(d.line) + ": " + m;
}

std::string tableCell(const Outcome& o) {
  if (!o.loaded) {
    const io::Diagnostic& d = o.refusal.front();
    return "refused: " + (d.line > 0 ? brief(d) : d.message.substr(0, d.message.find(',')));
  }
  if (o.read.warnings.empty()) return "loaded";
  std::string s = "loaded with " + std::to_string(o.read.warnings.size()) + " kind" +
                  (o.read.warnings.size() == 1 ? "" : "s") + " of warning: ";
  for (std::size_t i = 0; i < o.read.warnings.size(); ++i) s += (i ? "; " : "") + brief(o.read.warnings[i]);
  return s;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: real_boards_survey DIR --unlisted FILE [--shard K/N] [--table FILE]\n");
    return 2;
  }
  const fs::path dir = argv[1];
  int shard = 0, shards = 1;
  std::string table, unlisted;
  for (int i = 2; i + 1 < argc; i += 2) {
    if (std::strcmp(argv[i], "--shard") == 0) std::sscanf(argv[i + 1], "%d/%d", &shard, &shards);
    else if (std::strcmp(argv[i], "--table") == 0) table = argv[i + 1];
    else if (std::strcmp(argv[i], "--unlisted") == 0) unlisted = argv[i + 1];
  }
  if (unlisted.empty()) {
    std::fprintf(stderr, "real_boards_survey: --unlisted FILE is required\n");
    return 2;
  }
  if (!fs::is_directory(dir) || !fs::exists(dir / "SOURCES.md")) {
    const char* ci = std::getenv("CI");
    const bool inCi = ci != nullptr && std::strcmp(ci, "true") == 0;
    std::fprintf(stderr,
                 "%s: this test reads the real-board collection, which is not at %s (it lies beside "
                 "the source tree, as ../shared/boards/real, and does not come with a clone)%s\n",
                 inCi ? "FAIL" : "SKIP", dir.string().c_str(), inCi ? "; CI must have it" : "");
    return inCi ? 1 : kSkipped;
  }
  std::map<std::string, BoardKind> kinds;
  try {
    kinds = realboards::readBoardKinds((dir / "SOURCES.md").string(), unlisted);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "FAIL: %s\n", e.what());
    return 1;
  }
  std::vector<std::string> files;
  for (const auto& entry : fs::directory_iterator(dir))
    if (entry.is_regular_file() && entry.path().filename() != "SOURCES.md")
      files.push_back(entry.path().filename().string());
  std::sort(files.begin(), files.end());

  int failed = 0, checked = 0;
  std::map<std::string, std::array<int, 3>> totals;  // "S text" → loaded, with warnings, refused
  std::string rows;
  for (std::size_t i = 0; i < files.size(); ++i) {
    if (static_cast<int>(i % static_cast<std::size_t>(shards)) != shard) continue;
    const auto k = kinds.find(files[i]);
    if (k == kinds.end()) {
      std::printf("FAIL %s: its kind is neither in SOURCES.md nor in unlisted.tsv\n", files[i].c_str());
      ++failed;
      continue;
    }
    const Outcome o = survey(dir / files[i], k->second);
    ++checked;
    for (const std::string& f : o.failures)
      std::printf("FAIL %s (%c): %s\n", files[i].c_str(), k->second.kind, f.c_str());
    failed += o.failures.empty() ? 0 : 1;
    const std::string group =
        std::string(1, k->second.kind) + " " + (realboards::isBoardFormat(k->second) ? "text/XML" : "other");
    auto& t = totals[group];
    ++t[!o.loaded ? 2 : o.read.warnings.empty() ? 0 : 1];
    rows += "| `" + files[i] + "` | " + k->second.kind + " | " + k->second.format + " | " + tableCell(o) + " |\n";
  }
  std::printf("%d files checked, %d broke their kind's expectations\n", checked, failed);
  for (const auto& [group, t] : totals)
    std::printf("  %-12s loaded %d, loaded with warnings %d, refused %d\n", group.c_str(), t[0], t[1], t[2]);
  if (!table.empty()) {
    std::ofstream out(table);
    out << "| kind | format | loaded | loaded with warnings | refused |\n|---|---|---|---|---|\n";
    for (const auto& [group, t] : totals)
      out << "| " << group.substr(0, 1) << " | " << group.substr(2) << " | " << t[0] << " | " << t[1] << " | " << t[2]
          << " |\n";
    out << "\n| file | kind | format | outcome |\n|---|---|---|---|\n" << rows;
  }
  return failed == 0 ? 0 : 1;
}
