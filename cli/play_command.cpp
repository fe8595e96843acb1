// `gizmo play`: checks the board, the options and the play module, then writes the page whole.
// Bad input is refused with exit code 2 before anything is written.
#include "play_command.hpp"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "board_input.hpp"
#include "play_page.hpp"
#include "render_output.hpp"
#include "run_options.hpp"

#ifndef GIZMO_PLAY_MODULE_DEFAULT
#define GIZMO_PLAY_MODULE_DEFAULT ""
#endif

namespace gizmo::cli {
namespace {

int fail(const std::string& message) {
  std::cerr << "gizmo play: " << message << '\n';
  return kExitBadInput;
}

bool endsWith(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// Where the play module is: --module, else $GIZMO_PLAY_MODULE, else where this build's wasm32
// cross build puts it.
std::string modulePath(const PlayOptions& o) {
  if (!o.module.empty()) return o.module;
  if (const char* env = std::getenv("GIZMO_PLAY_MODULE"); env && *env) return env;
  return GIZMO_PLAY_MODULE_DEFAULT;
}

// The module's text, or a message saying why there is none and how to build it.
bool readModule(const std::string& path, std::string& text, std::string& why) {
  const std::string howToBuild =
      "the play module is the wasm32 cross build's web/gizmo-play.js: scripts/dev play-module builds it "
      "(about five minutes the first time), or give one with --module FILE or GIZMO_PLAY_MODULE";
  std::error_code error;
  if (path.empty() || !std::filesystem::is_regular_file(path, error)) {
    why = "the WebAssembly play module is not built" + (path.empty() ? std::string() : " (no " + path + ")") + "; " +
          howToBuild;
    return false;
  }
  std::ifstream in(path, std::ios::binary);
  std::ostringstream buffer;
  buffer << in.rdbuf();
  text = buffer.str();
  if (!in || text.find("GizmoPlayModule") == std::string::npos) {
    why = path + ": not a play module (it does not define GizmoPlayModule); " + howToBuild;
    return false;
  }
  return true;
}

}  // namespace

int playCommand(const PlayOptions& o) {
  if (!endsWith(o.output, ".html")) return fail("-o must name the page to write, a .html file");
  RunOptions run;
  run.board = o.board;
  run.model = o.model;
  run.maxTick = o.maxTick;
  run.strict = o.strict;
  CheckedRun checked;
  int code = kExitOk;
  if (!checkRun(run, "play", checked, code)) return code;
  std::string module, why;
  if (!readModule(modulePath(o), module, why)) return fail(why);
  PlayPage page;
  page.game.title = o.board.empty() ? checked.boardName : std::filesystem::path(o.board).filename().string();
  page.game.board = checked.request.board;
  page.game.boardWarnings = checked.boardWarnings;
  page.game.model = checked.request.model;
  page.game.maxTick = checked.request.maxTick;
  page.module = std::move(module);
  try {
    writeFileWhole(o.output, playHtml(page));
  } catch (const std::exception& e) {
    return fail(e.what());
  }
  std::cout << o.output << ": " << page.game.title << ", " << motionModelName(page.game.model) << " model, ticks of "
            << page.game.maxTick << " s; open it in a browser to play\n";
  return kExitOk;
}

}  // namespace gizmo::cli
