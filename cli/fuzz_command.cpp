#include "fuzz_command.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <unistd.h>

#include "board_input.hpp"
#include "gizmo/verify/fuzz/campaign.hpp"
#include "gizmo/verify/fuzz/expectations.hpp"
#include "gizmo/verify/fuzz/properties.hpp"
#include "gizmo/verify/fuzz/run_description.hpp"

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
    if (!c.message.empty()) std::cout << "  " << c.message << '\n';
  }
}

// --check: the properties on one run read from files, then the user's expectations about it (a
// run as long as the longest time they allow). A malformed expectation file is refused before
// anything is checked.
int checkOne(const FuzzOptions& o, const std::vector<const fz::Property*>& properties) {
  CheckedRun run;
  int code = kExitOk;
  RunOptions options = o.run;
  options.board = o.check;
  if (!checkRun(options, "fuzz", run, code)) return code;
  std::vector<fz::Expectation> expectations;
  try {
    if (!o.expect.empty()) expectations = fz::readExpectationFile(o.expect);
  } catch (const fz::ExpectationError& e) {
    std::cerr << "gizmo fuzz: " << e.what() << '\n';
    return kExitBadInput;
  }
  std::vector<fz::ExpectationFailure> broken;
  try {
    if (!expectations.empty()) broken = fz::checkExpectations(run.request, expectations);
  } catch (const fz::ExpectationError& e) {
    std::cerr << "gizmo fuzz: " << e.what() << '\n';
    return kExitBadInput;
  }
  int result = kExitOk;
  const std::vector<fz::PropertyResult> results = fz::checkProperties(properties, run.request);
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
    const auto failed = std::find_if(broken.begin(), broken.end(),
                                     [k](const fz::ExpectationFailure& f) { return f.expectation == k; });
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

}  // namespace

std::string fuzzPropertyList() { return fz::propertyNames(); }

int fuzzCommand(const FuzzOptions& o) {
  if (!o.merge.empty()) return mergeResults(o);
  std::vector<const fz::Property*> properties;
  if (!chooseProperties(o.property, properties)) return kExitBadInput;
  if (!o.check.empty()) return checkOne(o, properties);
  if (o.boardTimeGiven) {
    // Before --budget had its name, a campaign's --time was seconds of wall time: say so rather
    // than run a campaign that ignores it.
    std::cerr << "gizmo fuzz: --time is seconds of board time, for --check; a campaign's wall-time limit is --budget\n";
    return kExitBadInput;
  }

  fz::CampaignOptions c;
  c.properties = properties;
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
    c.stop = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() > o.wallSeconds; };
  const bool tty = ::isatty(STDERR_FILENO);
  c.progress = [&](std::uint64_t done, std::uint64_t planned, std::uint64_t failures) {
    // On a terminal one line that updates itself; in a log, a line every tenth of the way.
    if (tty) std::cerr << "\rgizmo fuzz: " << done << "/" << planned << " cases, " << failures << " failures" << std::flush;
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
  std::cerr << "gizmo fuzz: seed " << o.seed << ", " << o.count << " cases"
            << (o.shard.empty() ? std::string() : ", shard " + o.shard) << ", " << o.jobs << " jobs, properties "
            << o.property << '\n';
  fz::CampaignResult result = fz::runCampaign(c);
  if (tty) std::cerr << '\n';
  if (!o.out.empty()) {
    try {
      fz::writeCampaign(result, o.out, "gizmo");
    } catch (const fz::CampaignError& e) {
      std::cerr << "gizmo fuzz: " << e.what() << '\n';
      return kExitBadInput;
    }
  }
  std::cout << "fuzz: " << fz::summaryLine(result) << '\n';
  printFailures(result);
  return fz::failureCount(result) == 0 ? kExitOk : kExitCheckFailed;
}

}  // namespace gizmo::cli
