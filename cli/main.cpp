// The `gizmo` command: one subcommand per task, each a thin layer over the libraries.
// CLI11 lives in this one translation unit (it is slow to compile). The portable build
// (GIZMO_PORTABLE, docs/determinism.md) has run, record, replay, dump and diff; verify,
// crosscheck, fuzz, study and render exist in the full build only.
#include <CLI/CLI.hpp>
#include <iostream>

#include "board_input.hpp"
#include "log_commands.hpp"
#include "run_command.hpp"
#ifndef GIZMO_PORTABLE
#include "crosscheck_command.hpp"
#include "fuzz_command.hpp"
#include "play_command.hpp"
#include "render_command.hpp"
#include "study_command.hpp"
#include "verify_command.hpp"
#endif

int main(int argc, char** argv) {
  using namespace gizmo::cli;
  CLI::App app{
      "gizmo — deterministic Gizmoball simulation, replay and verification.\n\n"
      "Exit codes: 0 ok, 1 a check failed, 2 bad input or usage."};
  app.require_subcommand(1);

  int code = kExitOk;

  RunOptions run;
  CLI::App* runCmd =
      app.add_subcommand("run",
                         "Simulate a board and print the final state and the count of each event kind.\n"
                         "Example: gizmo run fixtures/boards/spec-example.xml --time 30 --model classic");
  addRunOptions(*runCmd, run);
  runCmd->add_flag("--json", run.json, "Print one JSON object instead of text");
  runCmd->callback([&] { code = runCommand(run); });

  RecordOptions record;
  CLI::App* recordCmd =
      app.add_subcommand("record",
                         "Simulate a board and write every decision to a replay log.\n"
                         "Example: gizmo record --time 60 -o run.gzlog\n"
                         "Branch: gizmo record --from run.gzlog --at 12.5 --keys new.keys -o branch.gzlog");
  addRunOptions(*recordCmd, record.run);
  recordCmd->add_option("-o,--output", record.output, "The log file to write")->required();
  recordCmd->add_flag("--json", record.run.json, "Print the run's summary as one JSON object");
  CLI::Option* from = recordCmd->add_option(
      "--from", record.from,
      "Branch: go on from a moment of this log (--at or --event) with new key input (--keys, or none);\n"
      "--time is then the board time the branch runs to (default: the log's). docs/replay-format.md");
  for (const char* name : {"board", "--model", "--precision", "--max-tick", "--strict"})
    from->excludes(recordCmd->get_option(name));
  CLI::Option* at =
      recordCmd->add_option("--at", record.at, "With --from: the board time to branch at (seconds)")->needs(from);
  recordCmd->add_option("--event", record.event, "With --from: branch after this many of the log's events")
      ->needs(from)
      ->excludes(at);
  recordCmd->callback([&] {
    record.timeGiven = recordCmd->get_option("--time")->count() > 0;
    code = recordCommand(record);
  });

  ReplayOptions replay;
  CLI::App* replayCmd = app.add_subcommand(
      "replay",
      "Run a log's board again and compare every decision with the log (exit 1 at the first difference),\n"
      "or with --at/--event show the state at one moment, reached from the nearest keyframe.");
  replayCmd->add_option("log", replay.log, "The replay log")->required();
  replayCmd->add_option("--at", replay.at, "Show the state at this board time (seconds)");
  replayCmd->add_option("--event", replay.event, "Show the state after this many events");
  replayCmd->add_flag("--json", replay.json, "Print one JSON object");
  replayCmd->add_flag("--every-record", replay.everyRecord,
                      "Encode the run and compare it with the log record by record, not by each chunk's digest\n"
                      "(slower; a difference is always found and shown this way)");
  replayCmd->callback([&] { code = replayCommand(replay); });

  DiffOptions diff;
  CLI::App* diffCmd = app.add_subcommand("diff", "Find the first decision where two logs part (exit 1 when they do).");
  diffCmd->add_option("first", diff.first, "The first log")->required();
  diffCmd->add_option("second", diff.second, "The second log")->required();
  diffCmd->add_flag("--summary", diff.summary, "Also count every kind of decision in both logs");
  diffCmd->add_option("--context", diff.context, "Decisions shown around the parting")
      ->capture_default_str()
      ->check(CLI::Range(0, 1000));
  diffCmd->add_flag("--json", diff.json, "Print one JSON object");
  diffCmd->callback([&] { code = diffCommand(diff); });

  DumpOptions dump;
  CLI::App* dumpCmd = app.add_subcommand("dump", "Print a log's decisions, one line each.");
  dumpCmd->add_option("log", dump.log, "The replay log")->required();
  dumpCmd->add_flag("--json", dump.json, "One JSON object per line");
  dumpCmd->add_flag("--exact", dump.exact, "Values as exact hex floats instead of 17 significant digits");
  dumpCmd->add_option("--kind", dump.kind, "Only this event kind, decision type or model rule");
  dumpCmd->add_option("--gizmo", dump.gizmo, "Only decisions that involve this gizmo");
  dumpCmd->add_option("--from", dump.from, "Only decisions made at or after this board time");
  dumpCmd->add_option("--to", dump.to, "Only decisions made at or before this board time");
  dumpCmd->callback([&] { code = dumpCommand(dump); });

#ifndef GIZMO_PORTABLE
  VerifyOptions verify;
  CLI::App* verifyCmd = app.add_subcommand(
      "verify",
      "Run a board at every rung of the precision ladder and compare each run's decisions with a reference\n"
      "run: how long each agrees, its largest errors, its energy drift and its cost.\n"
      "Example: gizmo verify --time 10 --precisions double,long-double,mpfr:256 --json");
  addRunOptions(*verifyCmd, verify.run, false);
  verifyCmd->add_option(
      "--precisions", verify.precisions,
      std::string("Comma-separated rungs (default: all but rational, and rational where the scene allows): ") +
          gizmo::kPrecisionNames);
  verifyCmd->add_option("--reference", verify.reference,
                        "The run to compare with (default: rational where the scene "
                        "allows, else mpfr:256)");
  verifyCmd
      ->add_option("--exact-digits", verify.exactDigits,
                   "Stop an exact (rational) run once its board time has this many digits")
      ->capture_default_str()
      ->check(CLI::Range(std::size_t(100), std::size_t(100000000)));
  CLI::Option* certify = verifyCmd->add_flag(
      "--certify", verify.certify,
      "Check a recorded double run (give its log instead of a board) decision by decision with interval arithmetic;\n"
      "exit 1 when a decision is proven wrong");
  for (const char* runOnly :
       {"--time", "--model", "--max-tick", "--keys", "--precisions", "--reference", "--exact-digits"})
    certify->excludes(verifyCmd->get_option(runOnly));
  verifyCmd->add_flag("--json", verify.run.json, "Print one JSON object");
  verifyCmd->callback([&] { code = verifyCommand(verify); });

  CrosscheckCommandOptions crosscheck;
  CLI::App* crosscheckCmd = app.add_subcommand(
      "crosscheck",
      "Run a board in our simulator and in Box2D at each step size and match their collisions: what\n"
      "agreed and how closely, what either side missed, trajectory and energy divergence, cost.\n"
      "With --trace FILE: another engine's run of the board, read from JSON lines (docs/verification.md).\n"
      "With --toi-sweeps N: our times of impact against b2TimeOfImpact on N random sweeps per feature kind.\n"
      "Example: gizmo crosscheck fixtures/boards/box2d/speed-cap.txt --time 2 --dt 1/60,1/240 --json");
  addRunOptions(*crosscheckCmd, crosscheck.run, false);
  std::vector<CLI::Option*> box2dOptions;
  box2dOptions.push_back(
      crosscheckCmd
          ->add_option("--dt", crosscheck.steps, "Box2D step sizes, seconds, comma-separated (a number or 1/N)")
          ->capture_default_str());
  box2dOptions.push_back(
      crosscheckCmd
          ->add_option("--engine", crosscheck.engine, "box2d-2.4 (linked in) or box2d-v3 (box2d3-wasm under node)")
          ->capture_default_str());
  box2dOptions.push_back(crosscheckCmd->add_flag("--no-bullet", crosscheck.noBullet,
                                                 "Balls are not bullets (Box2D may let two fast balls pass)"));
  box2dOptions.push_back(crosscheckCmd->add_flag("--no-continuous", crosscheck.noContinuous,
                                                 "No continuous collision at all (Box2D may let a ball pass a gizmo)"));
  box2dOptions.push_back(
      crosscheckCmd
          ->add_option("--restitution-threshold", crosscheck.restitutionThreshold,
                       "Box2D's restitution threshold, m/s (its default is 1: slower hits do not bounce)")
          ->capture_default_str());
  box2dOptions.push_back(
      crosscheckCmd->add_option("--toi-sweeps", crosscheck.toiSweeps,
                                "Compare times of impact on this many seeded random sweeps per feature kind instead"));
  box2dOptions.push_back(
      crosscheckCmd->add_option("--seed", crosscheck.seed, "The sweeps' seed")->capture_default_str());
  box2dOptions.push_back(crosscheckCmd->add_option(
      "--path-out", crosscheck.pathOut,
      "Write Box2D's ball paths (one --dt) to this file, for gizmo render LOG --compare FILE"));
  box2dOptions.push_back(crosscheckCmd->add_option(
      "--trace-out", crosscheck.traceOut,
      "With --engine box2d-v3 and one --dt: the v3 program also writes its run to this file as a trace (for --trace)"));
  crosscheckCmd->add_option(
      "--trace", crosscheck.trace,
      "Compare with another engine's run of the board, read from this trace (JSON lines) instead of Box2D");
  crosscheckCmd->add_flag("--json", crosscheck.run.json, "Print one JSON object");
  crosscheckCmd->callback([&] {
    for (const CLI::Option* option : box2dOptions)
      if (option->count() > 0 && crosscheck.box2dOptionGiven.empty()) crosscheck.box2dOptionGiven = option->get_name();
    code = crosscheckCommand(crosscheck);
  });

  FuzzOptions fuzz;
  CLI::App* fuzzCmd = app.add_subcommand(
      "fuzz",
      "Check properties (docs/fuzzing.md) on generated boards, or on variations of a BOARD or replay log of yours\n"
      "(its key input, ball launches, gravity, friction, model and tick) with your --expect file; each failure is\n"
      "shrunk (a generated board to a minimal board, a variation back toward your run) and, with --out, written\n"
      "there with its key script, its log and a command that checks it again (exit 1).\n"
      "Examples: gizmo fuzz --count 200 --jobs 2 --out fuzz-results\n"
      "          gizmo fuzz my-board.txt --expect my-board.expect --count 500 --jobs 2 --out found");
  fuzzCmd->add_option("board", fuzz.board,
                      "A board file or replay log whose variations to check (none: generated boards)");
  fuzzCmd->add_option("--property", fuzz.property, "all, or one of: " + fuzzPropertyList())->capture_default_str();
  fuzzCmd->add_option("--count", fuzz.count, "Cases in the campaign, numbered from 0")->capture_default_str();
  fuzzCmd->add_option("--seed", fuzz.seed, "Campaign seed: case k is made from (seed, k) alone")->capture_default_str();
  fuzzCmd->add_option("--jobs", fuzz.jobs, "Threads")->capture_default_str();
  fuzzCmd->add_option("--shard", fuzz.shard, "K/N: only the cases k with k % N == K (one task of a job array)");
  fuzzCmd->add_option("--out", fuzz.out, "Folder for results.txt and one folder per failure");
  fuzzCmd->add_option("--budget", fuzz.wallSeconds,
                      "Stop starting new cases after this many seconds of wall time (the one option that makes a\n"
                      "campaign's result depend on the machine; the summary then says 'stopped early')");
  fuzzCmd->add_option("--shrink-budget", fuzz.shrinkBudget, "Property checks spent shrinking one failure")
      ->capture_default_str();
  fuzzCmd->add_flag("--log-cases", fuzz.logCases,
                    "Print a line to stderr as each case starts and as it ends (with its wall time), so that a "
                    "shard that goes quiet says which case it is on");
  fuzzCmd->add_flag("--json", fuzz.json, "Print the campaign's result as one JSON object");
  CLI::Option* fuzzMerge = fuzzCmd->add_option("--merge", fuzz.merge, "Merge the --out folders of a campaign's shards");
  CLI::Option* fuzzCheck = fuzzCmd->add_option("--check", fuzz.check, "Check the properties on this board instead");
  // --time is seconds of board time here as in run, record and verify: the run's length.
  CLI::Option* fuzzTime =
      fuzzCmd->add_option("--time", fuzz.run.time, "With --check or BOARD: seconds of board time to simulate")
          ->capture_default_str();
  CLI::Option* fuzzKeys = fuzzCmd->add_option("--keys", fuzz.run.keys, "With --check or BOARD: key script");
  fuzzCmd->add_option("--expect", fuzz.expect,
                      "With --check or BOARD: your expectations about the board (docs/fuzzing.md, \"Expectations\")");
  addStrictOption(*fuzzCmd, fuzz.run.strict);
  CLI::Option* fuzzModel = fuzzCmd->add_option("--model", fuzz.run.model, "With --check or BOARD: ballistic or classic")
                               ->capture_default_str();
  CLI::Option* fuzzMaxTick =
      fuzzCmd->add_option("--max-tick", fuzz.run.maxTick, "With --check or BOARD: maximum tick length, seconds")
          ->capture_default_str();
  CLI::Option* fuzzPrecision =
      fuzzCmd->add_option("--precision", fuzz.run.precision, "With --check or BOARD: the scalar, double or long-double")
          ->capture_default_str();
  // The variations of BOARD's run (docs/fuzzing.md, "Fuzzing your own board"): 0 or off switches one off.
  gizmo::verify::fuzz::VariationOptions& vary = fuzz.vary;
  const std::pair<const char*, std::pair<double*, const char*>> ranges[] = {
      {"--vary-keys", {&vary.keyPressesPer10s, "Key presses added per 10 s of board time, on average (0: none)"}},
      {"--vary-position", {&vary.position, "L a ball may move, where it still fits (0: none)"}},
      {"--vary-speed", {&vary.speed, "% a moving ball's speed may change (0: none)"}},
      {"--vary-angle", {&vary.angle, "Degrees a moving ball's direction may turn (0: none)"}},
      {"--vary-kick", {&vary.kick, "L/s a ball at rest may be given (0: none)"}},
      {"--vary-gravity", {&vary.gravity, "% gravity may change (0: none)"}},
      {"--vary-friction", {&vary.friction, "% each friction constant may change (0: none)"}}};
  std::vector<CLI::Option*> varyOptions;
  for (const auto& [flag, target] : ranges)
    varyOptions.push_back(
        fuzzCmd->add_option(flag, *target.first, target.second)->capture_default_str()->group("Variations of BOARD"));
  varyOptions.push_back(
      fuzzCmd->add_option("--vary-model", vary.model, "One case in four runs the other motion model (on|off)")
          ->capture_default_str()
          ->group("Variations of BOARD"));
  varyOptions.push_back(
      fuzzCmd
          ->add_option("--vary-max-tick", vary.maxTick, "One case in four halves or doubles the maximum tick (on|off)")
          ->capture_default_str()
          ->group("Variations of BOARD"));
  varyOptions.push_back(fuzzCmd
                            ->add_option("--vary-scalar", vary.scalar,
                                         "One case in four runs in the other of double and long double (on|off; off by "
                                         "default: long double differs between kinds of machine)")
                            ->capture_default_str()
                            ->group("Variations of BOARD"));
  fuzzMerge->excludes(fuzzCheck);
  for (const char* campaignOnly :
       {"--count", "--seed", "--jobs", "--shard", "--out", "--budget", "--shrink-budget", "--log-cases", "--json"}) {
    fuzzMerge->excludes(fuzzCmd->get_option(campaignOnly));
    fuzzCheck->excludes(fuzzCmd->get_option(campaignOnly));
  }
  for (CLI::Option* v : varyOptions) fuzzCheck->excludes(v);
  fuzzMerge->excludes(fuzzCmd->get_option("--property"));
  fuzzCmd->callback([&, fuzzTime, fuzzKeys, fuzzModel, fuzzMaxTick, fuzzPrecision, varyOptions] {
    fuzz.boardTimeGiven = fuzzTime->count() > 0;
    fuzz.precisionGiven = fuzzPrecision->count() > 0;
    fuzz.keysGiven = fuzzKeys->count() > 0;
    fuzz.modelGiven = fuzzModel->count() > 0;
    fuzz.maxTickGiven = fuzzMaxTick->count() > 0;
    if (fuzz.board.empty())
      for (CLI::Option* v : varyOptions)
        if (v->count() > 0) {
          std::cerr << "gizmo fuzz: " << v->get_name() << " varies a BOARD of yours: give one\n";
          code = kExitBadInput;
          return;
        }
    code = fuzzCommand(fuzz);
  });

  StudyOptions study;
  CLI::App* studyCmd = app.add_subcommand(
      "study",
      "The speed/accuracy study: every method (classic model over maximum tick lengths, ballistic model, each\n"
      "at every precision; Box2D over step sizes with and without bullets) on a suite of scenes, its cost\n"
      "and its errors against the ballistic mpfr:256 run, written as CSV, JSON, SVG charts and an HTML page.\n"
      "Example: gizmo study --quick --out study-quick");
  studyCmd->add_option("--scenes", study.scenes, "A folder holding suite.txt (default: the built-in fixtures/study)");
  studyCmd->add_option("--out", study.out, "The folder to write into")->capture_default_str();
  studyCmd->add_flag("--quick", study.quick, "A small plan on the scenes with a quick duration: a couple of minutes");
  studyCmd->add_option("--bench", study.bench,
                       "gizmo_bench --benchmark_format=json output to chart beside the runs (repeatable)");
  studyCmd->callback([&] { code = studyCommand(study); });

  RenderOptions render;
  CLI::App* renderCmd = app.add_subcommand(
      "render",
      "Draw a run or a board: a log as one self-contained HTML replay player (-o run.html), or a board\n"
      "(a board file, a log, or the built-in one) as an SVG picture (-o board.svg), optionally with a run's\n"
      "ball paths and collision points (--trace LOG). docs/render.md.\n"
      "Example: gizmo render run.gzlog -o run.html --compare run-mpfr.gzlog");
  renderCmd->add_option("input", render.input, "The log to play, or the board (or log) to draw");
  renderCmd->add_option("-o,--output", render.output, "The file to write: .html or .svg")->required();
  renderCmd->add_option("--compare", render.compare,
                        "Player: a second log of the same board, a path file (gizmo crosscheck --path-out) or\n"
                        "box2d:STEP (Box2D run here at that step size), laid over the first");
  addStrictOption(*renderCmd, render.strict);
  renderCmd->add_option("--trace", render.trace, "Picture: draw this log's ball paths and collision points");
  renderCmd->add_option(
      "--tolerance", render.tolerance,
      "Leave out ball path pieces that stay this close (L) to the one before (default 1e-3; 0 keeps all)");
  renderCmd->callback([&] { code = renderCommand(render); });

  PlayOptions play;
  CLI::App* playCmd = app.add_subcommand(
      "play",
      "Write one self-contained HTML page in which to play a board with the keyboard: the simulator runs in\n"
      "the page (WebAssembly), and the game saves as a replay log that gizmo replay checks. docs/play.md.\n"
      "Example: gizmo play fixtures/boards/spec-example.txt -o game.html");
  playCmd->add_option("board", play.board, "The board file (default: the built-in spec example)");
  playCmd->add_option("-o,--output", play.output, "The page to write, .html")->required();
  playCmd->add_option("--model", play.model, "Motion model: ballistic or classic")->capture_default_str();
  playCmd
      ->add_option("--max-tick", play.maxTick, "Maximum tick length, seconds: the page moves the board in whole ticks")
      ->capture_default_str();
  playCmd->add_option("--module", play.module,
                      "The play module to put into the page (default: $GIZMO_PLAY_MODULE, else the one\n"
                      "scripts/dev play-module builds)");
  addStrictOption(*playCmd, play.strict);
  playCmd->callback([&] { code = playCommand(play); });
#endif

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
