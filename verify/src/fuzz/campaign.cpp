#include "gizmo/verify/fuzz/campaign.hpp"

#include <algorithm>
#include <atomic>
#include <charconv>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "gizmo/core/board/game_board.hpp"
#include "gizmo/core/math/precision.hpp"
#include "gizmo/io/board_writer.hpp"
#include "gizmo/replay/checksum.hpp"
#include "gizmo/replay/replay.hpp"
#include "gizmo/verify/fuzz/run_description.hpp"
#include "gizmo/verify/fuzz/run_generator.hpp"
#include "gizmo/verify/fuzz/run_shrinker.hpp"
#include "gizmo/verify/fuzz/seeded_random.hpp"

namespace gizmo::verify::fuzz {
namespace fs = std::filesystem;
namespace {

constexpr const char* kResultsFile = "results.txt";
// Version 2 added the `cases` line; a version 1 file holds generated cases.
constexpr const char* kResultsMagic = "gizmo-fuzz-results 2";
constexpr const char* kResultsMagicV1 = "gizmo-fuzz-results 1";

// A property that throws does not hold: the exception is what it says.
PropertyResult checkSafely(const Property& p, const RunRequest& run, Precision scalar) {
  const Property* const one[] = {&p};
  return checkProperties(one, run, scalar).front();
}

std::string hex(std::uint64_t x) {
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(x));
  return buf;
}

std::string shortest(double x) {
  char buf[64];
  return std::string(buf, std::to_chars(buf, buf + sizeof buf, x).ptr);
}

void writeFile(const fs::path& path, const std::string& content) {
  std::ofstream out(path, std::ios::binary);
  out << content;
  if (!out.flush()) throw CampaignError("cannot write " + path.string());
}

std::string quoted(const std::string& s) {
  if (s.find_first_of(" '\"\\$`") == std::string::npos) return s;
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

// failure.txt's word on run.gzlog when the log stops before the run's end.
std::string logExtent(const RunRequest& run, const RunRequest& logged) {
  if (logged.duration == run.duration) return "";
  return "\nrun.gzlog holds the run up to t = " + shortest(logged.duration) +
         ", the end of the tick in which it failed; the run goes on to t = " + shortest(run.duration) + ".\n";
}

}  // namespace

int caseSize(std::uint64_t index) { return int(index % std::uint64_t(kMaxSize + 1)); }

RunRequest caseRun(std::uint64_t campaignSeed, std::uint64_t index) {
  return generateRun(caseSeed(campaignSeed, index), caseSize(index));
}

namespace {

class GeneratedSource final : public CaseSource {
 public:
  Case make(std::uint64_t campaignSeed, std::uint64_t index) const override { return {caseRun(campaignSeed, index)}; }
  Shrunk shrink(std::uint64_t, std::uint64_t, const RunRequest& failing, const Fails& fails,
                std::size_t budget) const override {
    const Minimised m = minimise(
        failing, [&](const RunRequest& r) { return fails(r, Precision::Double); }, budget);
    return {m.run, Precision::Double, m.steps, ""};
  }
  std::string describe() const override { return "generated"; }
};

}  // namespace

const CaseSource& generatedCases() {
  static const GeneratedSource source;
  return source;
}

VariationSource::VariationSource(RunRequest base, VariationOptions options, Precision scalar)
    : base_(std::move(base)), options_(options), scalar_(scalar) {}

Departure VariationSource::departure(std::uint64_t campaignSeed, std::uint64_t index) const {
  if (index == 0) return {};  // case 0: the user's run as given
  return randomDeparture(base_, caseSeed(campaignSeed, index), options_);
}

CaseSource::Case VariationSource::make(std::uint64_t campaignSeed, std::uint64_t index) const {
  const Departure d = departure(campaignSeed, index);
  return {applyDeparture(base_, d), scalarOf(scalar_, d)};
}

CaseSource::Shrunk VariationSource::shrink(std::uint64_t campaignSeed, std::uint64_t index, const RunRequest&,
                                           const Fails& fails, std::size_t budget) const {
  const ShrunkDeparture s = shrinkDeparture(
      base_, departure(campaignSeed, index),
      [&](const RunRequest& r, const Departure& d) { return fails(r, scalarOf(scalar_, d)); }, budget,
      options_.shortestRun);
  return {applyDeparture(base_, s.departure), scalarOf(scalar_, s.departure), s.steps,
          describeDeparture(base_, s.departure, scalar_)};
}

std::string VariationSource::describe() const {
  const std::string run = describeRun(base_);
  const std::uint64_t h = replay::checksum64({reinterpret_cast<const std::uint8_t*>(run.data()), run.size()});
  const VariationOptions& o = options_;
  return "variations of run " + hex(h) + " keys " + shortest(o.keyPressesPer10s) + " position " + shortest(o.position) +
         " speed " + shortest(o.speed) + " angle " + shortest(o.angle) + " kick " + shortest(o.kick) + " gravity " +
         shortest(o.gravity) + " friction " + shortest(o.friction) + " model " + (o.model ? "on" : "off") +
         " max-tick " + (o.maxTick ? "on" : "off") + (o.scalar ? " scalar on" : "") +
         (scalar_ == Precision::LongDouble ? " given long-double" : "");
}

CampaignResult runCampaign(const CampaignOptions& o) {
  if (o.shards == 0 || o.shard >= o.shards)
    throw CampaignError("shard " + std::to_string(o.shard) + " of " + std::to_string(o.shards) + " does not exist");
  const CaseSource& source = o.source ? *o.source : generatedCases();
  CampaignResult result;
  result.cases = source.describe();
  result.seed = o.seed;
  result.count = o.count;
  for (const Property* p : o.properties)
    result.properties += (result.properties.empty() ? "" : ",") + std::string(p->name);
  result.shards = o.shards;
  result.shardsIncluded = {o.shard};

  std::vector<std::uint64_t> planned;
  for (std::uint64_t k = o.shard; k < o.count; k += o.shards) planned.push_back(k);
  std::vector<std::vector<CaseOutcome>> slots(planned.size());
  std::vector<char> ran(planned.size(), 0);
  std::atomic<std::size_t> next{0};
  std::atomic<bool> stopped{false};
  std::mutex progressMutex;
  std::uint64_t done = 0, failures = 0;

  auto work = [&] {
    for (;;) {
      if (stopped || (o.stop && o.stop())) {
        stopped = true;
        return;
      }
      const std::size_t slot = next++;
      if (slot >= planned.size()) return;
      const std::uint64_t index = planned[slot];
      if (o.caseStarted) {
        std::lock_guard<std::mutex> lock(progressMutex);
        o.caseStarted(index);
      }
      const auto [run, scalar] = source.make(o.seed, index);
      std::uint64_t failed = 0;
      const std::vector<PropertyResult> results = checkProperties(o.properties, run, scalar);
      for (std::size_t k = 0; k < o.properties.size(); ++k) {
        const Property* p = o.properties[k];
        CaseOutcome c;
        c.index = index;
        c.seed = caseSeed(o.seed, index);
        c.size = caseSize(index);
        c.property = std::string(p->name);
        const PropertyResult& r = results[k];
        c.holds = r.holds;
        c.fingerprint = r.fingerprint;
        if (!r.holds) {
          ++failed;
          const CaseSource::Shrunk m = source.shrink(
              o.seed, index, run,
              [&](const RunRequest& candidate, Precision s) { return !checkSafely(*p, candidate, s).holds; },
              o.shrinkBudget);
          c.minimal = m.run;
          c.scalar = m.scalar;
          c.shrinkSteps = m.steps;
          c.departure = m.departure;
          const PropertyResult minimal = checkSafely(*p, m.run, m.scalar);
          c.message = minimal.message;
          c.failedAt = minimal.failedAt;
        }
        slots[slot].push_back(std::move(c));
      }
      ran[slot] = 1;
      std::lock_guard<std::mutex> lock(progressMutex);
      ++done;
      failures += failed;
      if (o.caseFinished) o.caseFinished(index, failed);
      if (o.progress) o.progress(done, planned.size(), failures);
    }
  };
  const unsigned jobs = std::max(1u, o.jobs);
  std::vector<std::thread> threads;
  for (unsigned j = 1; j < jobs; ++j) threads.emplace_back(work);
  work();
  for (std::thread& t : threads) t.join();

  for (std::size_t s = 0; s < slots.size(); ++s) {
    if (!ran[s]) result.complete = false;
    for (CaseOutcome& c : slots[s]) result.outcomes.push_back(std::move(c));
  }
  return result;
}

std::uint64_t failureCount(const CampaignResult& r) {
  return std::uint64_t(
      std::count_if(r.outcomes.begin(), r.outcomes.end(), [](const CaseOutcome& c) { return !c.holds; }));
}

std::uint64_t casesChecked(const CampaignResult& r) {
  std::uint64_t cases = 0, last = ~std::uint64_t{0};
  for (const CaseOutcome& c : r.outcomes)
    if (c.index != last) ++cases, last = c.index;
  return cases;
}

std::uint64_t casesPlanned(const CampaignResult& r) {
  std::uint64_t cases = 0;
  for (std::uint64_t s : r.shardsIncluded)
    if (s < r.count) cases += (r.count - s + r.shards - 1) / r.shards;  // k = s, s + shards, … below count
  return cases;
}

std::string campaignDigest(const CampaignResult& r) {
  std::uint64_t h = 0xcbf29ce484222325ULL;
  auto mix = [&](std::uint64_t x) {
    for (int i = 0; i < 8; ++i) h = (h ^ ((x >> (8 * i)) & 0xff)) * 0x100000001b3ULL;
  };
  for (const CaseOutcome& c : r.outcomes) {
    mix(c.index);
    for (char ch : c.property) mix(std::uint64_t(static_cast<unsigned char>(ch)));
    mix(c.holds);
    mix(c.fingerprint);
  }
  return hex(h);
}

std::string summaryLine(const CampaignResult& r) {
  const std::size_t propertyCount = std::size_t(std::count(r.properties.begin(), r.properties.end(), ',')) + 1;
  std::ostringstream s;
  // A variation campaign's source, without its options: "variations of run HASH".
  if (r.cases != "generated") s << r.cases.substr(0, r.cases.find(" keys ")) << ", ";
  s << "seed " << r.seed << ", " << casesChecked(r) << " of " << r.count << " cases, " << propertyCount
    << " properties (" << r.properties << "): " << r.outcomes.size() << " checks, " << failureCount(r)
    << " failures, digest " << campaignDigest(r) << (r.complete ? "" : " (stopped early)");
  return s.str();
}

void writeCampaign(CampaignResult& r, const std::string& dir, const std::string& gizmo, const std::string& expectFile) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw CampaignError("cannot create " + dir + ": " + ec.message());
  std::ostringstream results;
  results << kResultsMagic << "\ncases " << r.cases << "\nseed " << r.seed << "\ncount " << r.count << "\nproperties "
          << r.properties << "\nshards " << r.shards << "\nshard";
  for (std::uint64_t s : r.shardsIncluded) results << ' ' << s;
  results << "\ncomplete " << (r.complete ? "yes" : "no") << "\n";
  for (CaseOutcome& c : r.outcomes) {
    if (!c.holds && c.folder.empty()) {
      c.folder = "failures/" + c.property + "-case" + std::to_string(c.index);
      const fs::path folder = fs::path(dir) / c.folder;
      fs::create_directories(folder, ec);
      if (ec) throw CampaignError("cannot create " + folder.string() + ": " + ec.message());
      writeFile(folder / "board.xml", io::writeXmlBoard(c.minimal.board));
      writeFile(folder / "keys.txt", writeKeyScript(c.minimal.keys));
      // The log goes as far as the failure's tick: a failure late in a long run of a crowded
      // board would otherwise write hundreds of megabytes that no one needs.
      const RunRequest logged = c.failedAt ? runThroughTickAt(c.minimal, *c.failedAt) : c.minimal;
      // A run that stops its own recording (a broken promise of the board's to the recorder, a
      // stall) is what a replay-identity failure may be: the log then holds the run up to its last
      // complete chunk, failure.txt says why it ends there, and the campaign goes on. Only a log
      // that cannot be written stops the campaign.
      std::string logStopped;
      try {
        replay::LogWriter log((folder / "run.gzlog").string());
        try {
          replay::recordRun(logged, PrecisionChoice{c.scalar, 0}, log);
        } catch (const StallError& e) {
          logStopped = e.what();
        } catch (const std::logic_error& e) {
          logStopped = e.what();
        }
      } catch (const std::exception& e) {
        throw CampaignError("cannot record " + (folder / "run.gzlog").string() + ": " + e.what());
      }
      if (!logStopped.empty())
        logStopped = "\nrun.gzlog stops where the run stopped its recording (" + logStopped +
                     "): it holds the run up to its last complete chunk.\n";
      const std::string command =
          gizmo + " fuzz --property " + c.property + " --check " + quoted((folder / "board.xml").string()) +
          " --keys " + quoted((folder / "keys.txt").string()) + " --model " +
          std::string(motionModelName(c.minimal.model)) + " --max-tick " + shortest(c.minimal.maxTick) + " --time " +
          shortest(c.minimal.duration) + (c.scalar == Precision::LongDouble ? " --precision long-double" : "") +
          (expectFile.empty() ? "" : " --expect " + quoted(expectFile));
      writeFile(folder / "command.txt", command + "\n");
      const std::string departure = c.departure.empty() ? "" : "departure from the run given: " + c.departure + "\n";
      if (!departure.empty()) writeFile(folder / "departure.txt", c.departure + "\n");
      writeFile(folder / "failure.txt", "property " + c.property + ", case " + std::to_string(c.index) + " (seed " +
                                            hex(c.seed) + ", size " + std::to_string(c.size) + "), shrunk in " +
                                            std::to_string(c.shrinkSteps) + " steps\n" + departure + c.message +
                                            "\n\n" + describeRun(c.minimal) +
                                            (logStopped.empty() ? logExtent(c.minimal, logged) : logStopped));
    }
    results << "case " << c.index << ' ' << hex(c.seed) << ' ' << c.size << ' ' << c.property << ' '
            << (c.holds ? "holds" : "fails") << ' ' << hex(c.fingerprint) << ' ' << (c.holds ? "-" : c.folder) << "\n";
  }
  // Written aside and renamed into place, so that a task killed while writing leaves no
  // results.txt (the merge then names the folder) rather than one cut short.
  const fs::path final = fs::path(dir) / kResultsFile,
                 partial = fs::path(dir) / (std::string(kResultsFile) + ".partial");
  writeFile(partial, results.str());
  fs::rename(partial, final, ec);
  if (ec) throw CampaignError("cannot write " + final.string() + ": " + ec.message());
}

CampaignResult readCampaign(const std::string& dir) {
  const fs::path path = fs::path(dir) / kResultsFile;
  std::ifstream in(path);
  if (!in) throw CampaignError(path.string() + ": cannot read (is " + dir + " the --out folder of a gizmo fuzz run?)");
  CampaignResult r;
  r.shardsIncluded.clear();
  std::string line;
  int lineNo = 0;
  auto bad = [&](const std::string& why) {
    return CampaignError(path.string() + ":" + std::to_string(lineNo) + ": " + why);
  };
  auto header = [&](const char* key) {
    ++lineNo;
    if (!std::getline(in, line) || line.rfind(std::string(key) + " ", 0) != 0)
      throw bad(std::string("expected '") + key + " …'");
    return line.substr(std::string(key).size() + 1);
  };
  auto number = [&](const std::string& s, int base = 10) {
    std::uint64_t v = 0;
    const auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), v, base);
    if (ec != std::errc() || p != s.data() + s.size() || s.empty()) throw bad("'" + s + "' is not a number");
    return v;
  };
  ++lineNo;
  if (!std::getline(in, line) || (line != kResultsMagic && line != kResultsMagicV1))
    throw bad("not a gizmo fuzz results file");
  r.cases = line == kResultsMagicV1 ? "generated" : header("cases");
  r.seed = number(header("seed"));
  r.count = number(header("count"));
  r.properties = header("properties");
  r.shards = number(header("shards"));
  if (r.shards == 0) throw bad("shards must be 1 or more");
  {
    std::istringstream s(header("shard"));
    for (std::string w; s >> w;) r.shardsIncluded.push_back(number(w));
  }
  const std::string complete = header("complete");
  if (complete != "yes" && complete != "no") throw bad("complete must be yes or no");
  r.complete = complete == "yes";
  while (std::getline(in, line)) {
    ++lineNo;
    std::istringstream s(line);
    std::string word, index, seed, size, holds, fingerprint;
    CaseOutcome c;
    if (!(s >> word >> index >> seed >> size >> c.property >> holds >> fingerprint >> c.folder) || word != "case" ||
        (holds != "holds" && holds != "fails") || (s >> word))
      throw bad("expected 'case INDEX SEED SIZE PROPERTY holds|fails FINGERPRINT FOLDER'");
    c.index = number(index);
    c.seed = number(seed, 16);
    c.size = int(number(size));
    c.holds = holds == "holds";
    c.fingerprint = number(fingerprint, 16);
    if (c.holds) c.folder.clear();
    if (c.index >= r.count ||
        std::find(r.shardsIncluded.begin(), r.shardsIncluded.end(), c.index % r.shards) == r.shardsIncluded.end())
      throw bad("case " + index + " is not a case of this file's shards");
    r.outcomes.push_back(std::move(c));
  }
  if (r.complete) {
    // Every check of every case of its shards, once each.
    std::set<std::pair<std::uint64_t, std::string>> seen;
    for (const CaseOutcome& c : r.outcomes) seen.emplace(c.index, c.property);
    const std::uint64_t properties = std::uint64_t(std::count(r.properties.begin(), r.properties.end(), ',')) + 1;
    const std::uint64_t expected = casesPlanned(r) * properties;
    if (seen.size() != r.outcomes.size() || seen.size() != expected)
      throw CampaignError(path.string() + ": says complete but holds " + std::to_string(r.outcomes.size()) +
                          " checks (" + std::to_string(seen.size()) + " different) of the " + std::to_string(expected) +
                          " its shards have: cut short or edited");
  }
  return r;
}

CampaignResult mergeCampaigns(const std::vector<std::pair<std::string, CampaignResult>>& parts) {
  if (parts.empty()) throw CampaignError("nothing to merge");
  const CampaignResult& first = parts.front().second;
  CampaignResult merged;
  merged.cases = first.cases;
  merged.seed = first.seed;
  merged.count = first.count;
  merged.properties = first.properties;
  merged.shards = first.shards;
  std::vector<std::string> owner(first.shards);
  for (const auto& [dir, part] : parts) {
    if (part.cases != first.cases || part.seed != first.seed || part.count != first.count ||
        part.properties != first.properties || part.shards != first.shards)
      throw CampaignError(dir +
                          " is from another campaign (cases, seed, count, properties or shard count differ from " +
                          parts.front().first + ")");
    for (std::uint64_t s : part.shardsIncluded) {
      if (s >= merged.shards)
        throw CampaignError(dir + " holds shard " + std::to_string(s) + " of " + std::to_string(merged.shards));
      if (!owner[s].empty())
        throw CampaignError("shard " + std::to_string(s) + " is in both " + owner[s] + " and " + dir);
      owner[s] = dir;
    }
    merged.complete = merged.complete && part.complete;
    for (CaseOutcome c : part.outcomes) {
      if (!c.folder.empty()) c.folder = (fs::path(dir) / c.folder).string();
      merged.outcomes.push_back(std::move(c));
    }
  }
  for (std::uint64_t s = 0; s < merged.shards; ++s)
    if (owner[s].empty())
      throw CampaignError("shard " + std::to_string(s) + " of " + std::to_string(merged.shards) + " is missing");
  for (std::uint64_t s = 0; s < merged.shards; ++s) merged.shardsIncluded.push_back(s);
  // Case order, and within a case the order the properties were checked in (kept by stable_sort).
  std::stable_sort(merged.outcomes.begin(), merged.outcomes.end(),
                   [](const CaseOutcome& a, const CaseOutcome& b) { return a.index < b.index; });
  return merged;
}

}  // namespace gizmo::verify::fuzz
