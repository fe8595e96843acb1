#include "fuzz_command.hpp"

#include <unistd.h>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>

#include <nlohmann/json.hpp>

#include "board_input.hpp"
#include "gizmo/verify/fuzz/campaign.hpp"
#include "gizmo/verify/fuzz/expectations.hpp"
#include "gizmo/verify/fuzz/properties.hpp"
#include "gizmo/verify/fuzz/run_description.hpp"
#include "log_view.hpp"

namespace gizmo::cli {
namespace {

namespace fz = gizmo::verify::fuzz;

bool chooseProperties(const std::string& name, std::vector<const fz::Property*>& out) {
  if (name == "all") {
    for (const fz::Property& p : fz::allProperties()) out.push_back(&p);
    return true;
  }
  if (const fz::Property* p = fz::findProperty(name)) {
    out.push_back(p);
    return true;
  }
  std::cerr << "gizmo fuzz: unknown property '" << name << "' (all, " << fz::propertyNames() << ")\n";
  return false;
}

// "K/N" with 0 <= K < N.
bool parseShard(const std::string& text, std::uint64_t& k, std::uint64_t& n) {
  unsigned long long a = 0, b = 0;
  int used = 0;
  if (std::sscanf(text.c_str(), "%llu/%llu%n", &a, &b, &used) != 2 || used != int(text.size()) || b == 0 || a >= b ||
      text[0] == '-' || text.find("/-") != std::string::npos) {
    std::cerr << "gizmo fuzz: --shard must be K/N with 0 <= K < N (e.g. 0/4), not '" << text << "'\n";
    return false;
  }
  k = a, n = b;
  return true;
}

void printFailures(const fz::CampaignResult& r) {
  for (const fz::CaseOutcome& c : r.outcomes) {
    if (c.holds) continue;
    std::cout << "FAIL " << c.property << " case " << c.index << " (seed " << c.seed << ", size " << c.size << ")";
    if (!c.folder.empty()) std::cout << ": " << c.folder;
    std::cout << '\n';
    if (!c.departure.empty()) std::cout << "  departure from the run given: " << c.departure << '\n';
    if (!c.message.empty()) std::cout << "  " << c.message << '\n';
  }
}

nlohmann::ordered_json campaignJson(const fz::CampaignResult& r) {
  nlohmann::ordered_json j;
  j["cases"] = r.cases;
  j["seed"] = r.seed;
  j["count"] = r.count;
  j["checked"] = fz::casesChecked(r);
  j["properties"] = r.properties;
  j["checks"] = r.outcomes.size();
  j["failures"] = fz::failureCount(r);
  j["complete"] = r.complete;
  j["summary"] = fz::summaryLine(r);
  j["digest"] = fz::campaignDigest(r);
  nlohmann::ordered_json failed = nlohmann::ordered_json::array();
  for (const fz::CaseOutcome& c : r.outcomes) {
    if (c.holds) continue;
    nlohmann::ordered_json f;
    f["property"] = c.property;
    f["case"] = c.index;
    f["message"] = c.message;
    if (!c.departure.empty()) f["departure"] = c.departure;
    f["shrink_steps"] = c.shrinkSteps;
    if (!c.folder.empty()) f["folder"] = c.folder;
    failed.push_back(std::move(f));
  }
  j["failed"] = std::move(failed);
  return j;
}

// The scalar of a fuzzed run: double or long double, the two the properties check in.
bool fuzzScalar(const PrecisionChoice& p, const std::string& what, Precision& scalar) {
  if (p.kind != Precision::Double && p.kind != Precision::LongDouble) {
    std::cerr << "gizmo fuzz: " << what << ": the properties check runs in double or long-double, not "
              << precisionName(p) << '\n';
    return false;
  }
  scalar = p.kind;
  return true;
}

// --check: the properties on one run read from files (none for `--property expectations`, a
// failure folder's command), then the user's expectations about it (a run as long as the longest
// time they allow).
int checkOne(const FuzzOptions& o, const std::vector<const fz::Property*>& properties,
             const std::vector<fz::Expectation>& expectations) {
  CheckedRun run;
  int code = kExitOk;
  RunOptions options = o.run;
  options.board = o.check;
  if (!checkRun(options, "fuzz", run, code)) return code;
  Precision scalar = Precision::Double;
  if (!fuzzScalar(run.precision, "--precision", scalar)) return kExitBadInput;
  std::vector<fz::ExpectationFailure> broken;
  try {
    if (!expectations.empty()) broken = fz::checkExpectations(run.request, expectations);
  } catch (const fz::ExpectationError& e) {
    std::cerr << "gizmo fuzz: " << e.what() << '\n';
    return kExitBadInput;
  }
  int result = kExitOk;
  const std::vector<fz::PropertyResult> results = fz::checkProperties(properties, run.request, scalar);
  for (std::size_t k = 0; k < properties.size(); ++k) {
    const fz::Property* p = properties[k];
    const fz::PropertyResult& r = results[k];
    std::cout << p->name << ": " << (r.holds ? "holds" : "FAILS") << '\n';
    if (!r.holds) {
      std::cout << "  " << r.message << '\n';
      result = kExitCheckFailed;
    }
  }
  for (std::size_t k = 0; k < expectations.size(); ++k) {
    const auto failed =
        std::find_if(broken.begin(), broken.end(), [k](const fz::ExpectationFailure& f) { return f.expectation == k; });
    std::cout << "expect " << expectations[k].source << ": " << (failed == broken.end() ? "holds" : "FAILS") << '\n';
    if (failed != broken.end()) {
      std::cout << "  " << failed->message << '\n';
      result = kExitCheckFailed;
    }
  }
  return result;
}

int mergeResults(const FuzzOptions& o) {
  std::vector<std::pair<std::string, fz::CampaignResult>> parts;
  fz::CampaignResult merged;
  try {
    for (const std::string& dir : o.merge) parts.emplace_back(dir, fz::readCampaign(dir));
    merged = fz::mergeCampaigns(parts);
  } catch (const fz::CampaignError& e) {
    std::cerr << "gizmo fuzz --merge: " << e.what() << '\n';
    return kExitBadInput;
  }
  std::cout << "fuzz: " << fz::summaryLine(merged) << '\n';
  // A shard that stopped early (its task's --budget ran out) is named, not only counted.
  for (const auto& [dir, part] : parts)
    if (!part.complete)
      std::cout << "INCOMPLETE " << dir << ": " << fz::casesChecked(part) << " of " << fz::casesPlanned(part)
                << " cases ran (stopped early)\n";
  printFailures(merged);
  return fz::failureCount(merged) == 0 ? kExitOk : kExitCheckFailed;
}

// Runs a campaign (generated boards, or variations when c.source is set) with the command's
// options, writes its folder, prints its summary, failures or JSON. Each failure's command checks
// the --expect file too, when there is one.
int runCampaignAndReport(const FuzzOptions& o, fz::CampaignOptions& c) {
  c.count = o.count;
  c.seed = o.seed;
  c.jobs = o.jobs;
  c.shrinkBudget = o.shrinkBudget;
  if (!o.shard.empty() && !parseShard(o.shard, c.shard, c.shards)) return kExitBadInput;
  if (o.jobs == 0 || o.jobs > 1024) {
    std::cerr << "gizmo fuzz: --jobs must be from 1 to 1024\n";
    return kExitBadInput;
  }
  if (!(o.wallSeconds >= 0)) {
    std::cerr << "gizmo fuzz: --budget must be a number of seconds, 0 or more\n";
    return kExitBadInput;
  }
  // The wall-clock budget belongs here, not in the library: it is the one thing that makes a
  // campaign's result depend on the machine (docs/fuzzing.md).
  const auto start = std::chrono::steady_clock::now();
  if (o.wallSeconds > 0)
    c.stop = [&] {
      return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() > o.wallSeconds;
    };
  const bool tty = ::isatty(STDERR_FILENO);
  c.progress = [&](std::uint64_t done, std::uint64_t planned, std::uint64_t failures) {
    // On a terminal one line that updates itself; in a log, a line every tenth of the way.
    if (tty)
      std::cerr << "\rgizmo fuzz: " << done << "/" << planned << " cases, " << failures << " failures" << std::flush;
    else if (done == planned || done % std::max<std::uint64_t>(1, planned / 10) == 0)
      std::cerr << "gizmo fuzz: " << done << "/" << planned << " cases, " << failures << " failures\n";
  };
  // Each case's start and end with its wall time, so that a shard that goes quiet names the case
  // it is on (a case can run for minutes: docs/fuzzing.md).
  std::vector<std::pair<std::uint64_t, std::chrono::steady_clock::time_point>> running;
  if (o.logCases) {
    c.caseStarted = [&](std::uint64_t index) {
      running.emplace_back(index, std::chrono::steady_clock::now());
      std::cerr << "gizmo fuzz: case " << index << " started\n";
    };
    c.caseFinished = [&](std::uint64_t index, std::uint64_t failed) {
      double seconds = 0;
      for (std::size_t k = 0; k < running.size(); ++k)
        if (running[k].first == index) {
          seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - running[k].second).count();
          running.erase(running.begin() + std::ptrdiff_t(k));
          break;
        }
      std::cerr << "gizmo fuzz: case " << index << " done in " << seconds << " s, "
                << (failed == 0 ? std::string("every property holds") : std::to_string(failed) + " failed") << '\n';
    };
  }
  std::cerr << "gizmo fuzz: " << (o.board.empty() ? std::string() : "variations of " + o.board + ", ") << "seed "
            << o.seed << ", " << o.count << " cases" << (o.shard.empty() ? std::string() : ", shard " + o.shard) << ", "
            << o.jobs << " jobs, properties " << o.property << (o.expect.empty() ? "" : " and expectations") << '\n';
  fz::CampaignResult result = fz::runCampaign(c);
  if (tty) std::cerr << '\n';
  if (!o.out.empty()) {
    try {
      fz::writeCampaign(result, o.out, "gizmo", o.expect);
    } catch (const fz::CampaignError& e) {
      std::cerr << "gizmo fuzz: " << e.what() << '\n';
      return kExitBadInput;
    }
  }
  if (o.json) {
    std::cout << campaignJson(result).dump(2) << '\n';
  } else {
    std::cout << "fuzz: " << fz::summaryLine(result) << '\n';
    printFailures(result);
  }
  return fz::failureCount(result) == 0 ? kExitOk : kExitCheckFailed;
}

// The run that `gizmo fuzz BOARD` varies, and its scalar: a board file read as `gizmo run` reads
// it (warnings included, --strict refusing them), or a replay log's board, model, tick, duration,
// key input and scalar, each replaced by the option given on the command line. A run in another
// scalar than double or long double (a float or MPFR log) is refused rather than varied in double.
bool baseRun(const FuzzOptions& o, RunRequest& base, Precision& scalar, int& code) {
  code = kExitBadInput;
  PrecisionChoice precision;
  std::string precisionFrom = "--precision";
  if (!isLogFile(o.board)) {
    CheckedRun run;
    RunOptions options = o.run;
    options.board = o.board;
    if (!checkRun(options, "fuzz", run, code)) return false;
    base = run.request;
    precision = run.precision;
  } else {
    CheckedOptions given;
    if (!checkRunOptions(o.run, "fuzz", given)) return false;
    std::optional<replay::OpenedLog> log = openLogFor("fuzz", o.board, code);
    if (!log) return false;
    if (o.run.strict && !log->header.boardWarnings.empty()) {
      std::cerr << "gizmo fuzz: " << o.board << ": --strict refuses a run of a board read leniently\n";
      return false;
    }
    // A log cut off still holds the whole run in its header, which is what is varied: say so.
    if (!log->reader.truncation().empty())
      std::cerr << "gizmo fuzz: " << o.board << ": " << log->reader.truncation()
                << "; its header holds the whole run given, which is what the campaign varies\n";
    base = log->request;
    precision = o.precisionGiven ? given.precision : log->precision;
    if (!o.precisionGiven) precisionFrom = o.board;
    try {
      if (o.keysGiven) base.keys = loadKeys(o.run.keys);
    } catch (const io::InputError& e) {
      std::cerr << e.what() << '\n';
      return false;
    }
    if (o.modelGiven) base.model = given.model;
    if (o.maxTickGiven) base.maxTick = o.run.maxTick;
    if (o.boardTimeGiven) base.duration = o.run.time;
  }
  code = kExitBadInput;  // checkRun set it to 0 when it read the board
  if (!fuzzScalar(precision, precisionFrom, scalar)) return false;
  code = kExitOk;
  return true;
}

bool checkVariations(const fz::VariationOptions& v) {
  const std::pair<const char*, double> ranges[] = {
      {"--vary-keys", v.keyPressesPer10s}, {"--vary-position", v.position}, {"--vary-speed", v.speed},
      {"--vary-angle", v.angle},           {"--vary-kick", v.kick},         {"--vary-gravity", v.gravity},
      {"--vary-friction", v.friction}};
  for (const auto& [flag, value] : ranges)
    if (!(value >= 0) || !(value <= 1e6)) {
      std::cerr << "gizmo fuzz: " << flag << " must be a number from 0 (off) up\n";
      return false;
    }
  if (v.speed >= 100 || v.friction > 100 || v.gravity > 100 || v.angle > 180) {
    std::cerr << "gizmo fuzz: --vary-speed must be under 100 (%), --vary-gravity and --vary-friction at most 100 (%), "
                 "--vary-angle at most 180 (degrees)\n";
    return false;
  }
  return true;
}

int boardCampaign(const FuzzOptions& o, std::vector<const fz::Property*> properties,
                  const std::vector<fz::Expectation>& expectations) {
  RunRequest base;
  Precision scalar = Precision::Double;
  int code = kExitOk;
  if (!baseRun(o, base, scalar, code)) return code;
  if (!checkVariations(o.vary)) return kExitBadInput;
  fz::VariationOptions vary = o.vary;
  std::optional<fz::Property> expected;
  if (!expectations.empty()) {
    // Every case runs at least as long as the expectations need, and shrinking cuts none shorter.
    const double horizon = fz::expectationHorizon(expectations);
    base.duration = std::max(base.duration, horizon);
    vary.shortestRun = std::max(vary.shortestRun, horizon);
    try {
      fz::checkExpectationNames(base, expectations);
    } catch (const fz::ExpectationError& e) {
      std::cerr << "gizmo fuzz: " << e.what() << '\n';
      return kExitBadInput;
    }
    expected = fz::expectationsProperty(expectations);
    properties.push_back(&*expected);
  }
  if (properties.empty()) {
    std::cerr << "gizmo fuzz: " << o.expect
              << " holds no expectation, and --property expectations asks for those alone\n";
    return kExitBadInput;
  }
  const fz::VariationSource source(base, vary, scalar);
  fz::CampaignOptions c;
  c.properties = properties;
  c.source = &source;
  return runCampaignAndReport(o, c);
}

}  // namespace

std::string fuzzPropertyList() { return fz::propertyNames() + ", " + std::string(fz::kExpectationsPropertyName); }

int fuzzCommand(const FuzzOptions& o) {
  if (!o.merge.empty()) return mergeResults(o);
  std::vector<const fz::Property*> properties;
  const bool onlyExpectations = o.property == fz::kExpectationsPropertyName;
  if (onlyExpectations && o.expect.empty()) {
    std::cerr << "gizmo fuzz: --property expectations needs --expect FILE\n";
    return kExitBadInput;
  }
  if (!onlyExpectations && !chooseProperties(o.property, properties)) return kExitBadInput;
  if (!o.check.empty() && !o.board.empty()) {
    std::cerr << "gizmo fuzz: give a BOARD to vary or --check one run, not both\n";
    return kExitBadInput;
  }
  // A malformed expectation file is refused before anything runs.
  std::vector<fz::Expectation> expectations;
  try {
    if (!o.expect.empty()) expectations = fz::readExpectationFile(o.expect);
  } catch (const fz::ExpectationError& e) {
    std::cerr << "gizmo fuzz: " << e.what() << '\n';
    return kExitBadInput;
  }
  if (!o.check.empty()) return checkOne(o, properties, expectations);
  if (!o.board.empty()) return boardCampaign(o, properties, expectations);
  if (o.boardTimeGiven) {
    // Before --budget had its name, a campaign's --time was seconds of wall time: say so rather
    // than run a campaign that ignores it.
    std::cerr << "gizmo fuzz: --time is seconds of board time, for --check or a BOARD; a campaign's wall-time limit is "
                 "--budget\n";
    return kExitBadInput;
  }
  if (o.keysGiven || o.modelGiven || o.maxTickGiven || o.precisionGiven || !o.expect.empty()) {
    std::cerr << "gizmo fuzz: --keys, --model, --max-tick, --precision and --expect describe a run: give --check BOARD "
                 "or a BOARD to vary\n";
    return kExitBadInput;
  }
  fz::CampaignOptions c;
  c.properties = properties;
  return runCampaignAndReport(o, c);
}

}  // namespace gizmo::cli
