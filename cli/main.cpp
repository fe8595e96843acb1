// The `gizmo` command: one subcommand per task, each a thin layer over the libraries.
// CLI11 lives in this one translation unit (it is slow to compile).
#include <CLI/CLI.hpp>
#include <iostream>

#include "board_input.hpp"
#include "run_command.hpp"

int main(int argc, char** argv) {
  using namespace gizmo::cli;
  CLI::App app{"gizmo — deterministic Gizmoball simulation, replay and verification.\n\n"
               "Exit codes: 0 ok, 1 a check failed, 2 bad input or usage."};
  app.require_subcommand(1);

  RunOptions run;
  CLI::App* runCmd = app.add_subcommand("run", "Simulate a board and print the final state and the count of each event kind.\n"
                                               "Example: gizmo run fixtures/boards/spec-example.xml --time 30 --model classic");
  runCmd->add_option("board", run.board, "Board file, XML or text (default: the specification's example, built in)");
  runCmd->add_option("--time", run.time, "Seconds of board time to simulate")->capture_default_str();
  runCmd->add_option("--model", run.model, "Motion model: ballistic or classic")->capture_default_str();
  runCmd->add_option("--precision", run.precision, "Scalar: float, double, long-double, float128, mpfr:BITS")
      ->capture_default_str();
  runCmd->add_option("--max-tick", run.maxTick, "Maximum tick length, seconds")->capture_default_str();
  runCmd->add_option("--keys", run.keys, "Key script: one 'TIME down|up KEYCODE' per line");
  runCmd->add_flag("--json", run.json, "Print one JSON object instead of text");
  int code = kExitOk;
  runCmd->callback([&] { code = runCommand(run); });

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return kExitBadInput;
  }
  return code;
}
