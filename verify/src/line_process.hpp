#pragma once
// A child program spoken to in lines: one socket is both its standard input and its standard
// output (its standard error stays the caller's), so that a request and its reply go back and
// forth without a file between them. The Box2D v3 engine uses it to step the node program
// (box2d3_run.cpp).
#include <sys/types.h>
#include <string>
#include <vector>

namespace gizmo::verify {

class LineProcess {
 public:
  // Starts `argv[0]`, found on the PATH, with those arguments; std::runtime_error when it cannot.
  // `name` names the program in every error.
  LineProcess(const std::vector<std::string>& argv, std::string name);
  ~LineProcess();
  LineProcess(const LineProcess&) = delete;
  LineProcess& operator=(const LineProcess&) = delete;

  // Writes `line` and a newline; std::runtime_error when the program has gone.
  void send(const std::string& line);
  // The next line it writes, without its newline; std::runtime_error, saying how the program
  // ended, when it ends first.
  std::string receive();
  // Closes the program's input and waits for it; its exit code (-1 when a signal ended it).
  int finish();

 private:
  std::string howItEnded();

  std::string name_;
  int socket_ = -1;
  pid_t pid_ = -1;
  std::string buffer_;  // read and not yet handed back
};

}  // namespace gizmo::verify
