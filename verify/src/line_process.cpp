#include "line_process.hpp"

#include <spawn.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <utility>

extern char** environ;

namespace gizmo::verify {

LineProcess::LineProcess(const std::vector<std::string>& argv, std::string name) : name_(std::move(name)) {
  int ends[2];
  if (::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, ends) != 0)
    throw std::runtime_error("cannot make a socket for " + name_ + ": " + std::strerror(errno));
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  // The child's end becomes its standard input and output (dup2 leaves them open across exec).
  posix_spawn_file_actions_adddup2(&actions, ends[1], STDIN_FILENO);
  posix_spawn_file_actions_adddup2(&actions, ends[1], STDOUT_FILENO);
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  const int error = ::posix_spawnp(&pid_, args[0], &actions, nullptr, args.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  ::close(ends[1]);
  if (error != 0) {
    ::close(ends[0]);
    throw std::runtime_error("cannot start " + name_ + ": " + std::strerror(error));
  }
  socket_ = ends[0];
}

LineProcess::~LineProcess() {
  if (pid_ > 0) finish();
}

void LineProcess::send(const std::string& line) {
  const std::string text = line + '\n';
  for (std::size_t sent = 0; sent < text.size();) {
    // MSG_NOSIGNAL: a program that has gone is an error here, not a SIGPIPE.
    const ssize_t n = ::send(socket_, text.data() + sent, text.size() - sent, MSG_NOSIGNAL);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw std::runtime_error(name_ + " stopped reading (" + howItEnded() + ")");
    sent += static_cast<std::size_t>(n);
  }
}

std::string LineProcess::receive() {
  for (;;) {
    const std::size_t end = buffer_.find('\n');
    if (end != std::string::npos) {
      std::string line = buffer_.substr(0, end);
      buffer_.erase(0, end + 1);
      return line;
    }
    char chunk[65536];
    const ssize_t n = ::recv(socket_, chunk, sizeof chunk, 0);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) throw std::runtime_error(name_ + " ended before its reply (" + howItEnded() + ")");
    buffer_.append(chunk, static_cast<std::size_t>(n));
  }
}

int LineProcess::finish() {
  if (pid_ <= 0) return -1;
  ::close(socket_);
  socket_ = -1;
  int status = 0;
  while (::waitpid(pid_, &status, 0) < 0 && errno == EINTR) {}
  pid_ = -1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::string LineProcess::howItEnded() {
  const int code = finish();
  return code < 0 ? std::string("killed") : "exit code " + std::to_string(code);
}

}  // namespace gizmo::verify
