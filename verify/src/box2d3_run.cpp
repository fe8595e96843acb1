// Runs verify/box2d3/run_scene.mjs under node on an exported scene and reads its trace back.
#include <unistd.h>

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <sys/wait.h>

#include "gizmo/verify/box2d3_run.hpp"

namespace gizmo::verify {
namespace {

namespace fs = std::filesystem;

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

// A word for the shell, whatever characters it holds.
std::string quoted(const std::string& word) {
  std::string out = "'";
  for (char c : word) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

// The scene, in a file of its own that is removed however the run ends.
class SceneFile {
 public:
  explicit SceneFile(const std::string& text) {
    static std::atomic<unsigned> counter{0};
    path_ = fs::temp_directory_path() /
            ("gizmo-box2d3-" + std::to_string(::getpid()) + "-" + std::to_string(counter++) + ".json");
    std::ofstream out(path_, std::ios::binary);
    out << text;
    if (!out.flush()) throw std::runtime_error("cannot write the Box2D v3 scene to " + path_.string());
  }
  ~SceneFile() {
    std::error_code ignored;
    fs::remove(path_, ignored);
  }
  SceneFile(const SceneFile&) = delete;
  SceneFile& operator=(const SceneFile&) = delete;
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
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

EngineTrace runBox2d3(const RunRequest& request, const Box2dOptions& options, double end) {
  if (const std::optional<std::string> why = box2d3Unavailable()) throw std::runtime_error(*why);
  const SceneFile scene(box2d3Scene(request, options));
  const std::string command = "node " + quoted((programDir() / "run_scene.mjs").string()) + " " + quoted(scene.path().string());
  FILE* pipe = ::popen(command.c_str(), "r");
  if (pipe == nullptr) throw std::runtime_error("cannot start node for the Box2D v3 run");
  std::string output;
  char buffer[65536];
  for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0;) output.append(buffer, n);
  const int status = ::pclose(pipe);
  if (status != 0)
    throw std::runtime_error("the Box2D v3 program failed (" +
                             (WIFEXITED(status) ? "exit code " + std::to_string(WEXITSTATUS(status)) : std::string("killed")) +
                             ")");
  std::istringstream in(output);
  try {
    return readEngineTrace(in, "the Box2D v3 program's trace", request.board, end);
  } catch (const EngineTraceError& e) {
    throw std::runtime_error(e.what());
  }
}

}  // namespace gizmo::verify
