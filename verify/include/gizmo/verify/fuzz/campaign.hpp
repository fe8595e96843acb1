#pragma once
// A fuzzing campaign: cases 0..count−1 of one seed, each a generated run checked against the
// chosen properties, on several threads, one shard of the cases at a time if asked; failures
// shrunk to a minimal run. Results are the same whatever the thread count and however the cases
// are cut into shards: case k is generated from (seed, k) alone, and results are kept in case
// order. Merging the shards' result folders gives what one unsharded run gives.
#include <cstdint>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "gizmo/core/run/run.hpp"
#include "gizmo/verify/fuzz/properties.hpp"
#include "gizmo/verify/fuzz/variations.hpp"

namespace gizmo::verify::fuzz {

// What a campaign's cases are: boards generated from the seed (the default), or variations of a
// run the user brought (`gizmo fuzz BOARD`). Case k is made from (campaign seed, k) alone either
// way, and a failing case is shrunk the way its source knows: to a minimal board, or back toward
// the user's run.
class CaseSource {
 public:
  virtual ~CaseSource() = default;
  // A case: its run, and the scalar its properties run in (Double, or LongDouble for a variation
  // that asks).
  struct Case {
    RunRequest run;
    Precision scalar = Precision::Double;
  };
  virtual Case make(std::uint64_t campaignSeed, std::uint64_t index) const = 0;
  // Whether a run in a scalar still fails.
  using Fails = std::function<bool(const RunRequest&, Precision)>;
  struct Shrunk {
    RunRequest run;
    Precision scalar = Precision::Double;
    std::size_t steps = 0;
    std::string departure;  // variations: the smallest departure from the user's run, in words
  };
  virtual Shrunk shrink(std::uint64_t campaignSeed, std::uint64_t index, const RunRequest& failing, const Fails& fails,
                        std::size_t budget) const = 0;
  // What results.txt says the cases are ("generated", or "variations of board HASH, …"): shards of
  // campaigns of different sources are never merged.
  virtual std::string describe() const = 0;
};

// Variations of `base`: case 0 is the base itself, case k > 0 the departure drawn from the case's
// seed. `describe` names the base by a hash of everything it is, and the options.
class VariationSource final : public CaseSource {
 public:
  // `scalar`: the base run's, Double or LongDouble (a log recorded in long double).
  VariationSource(RunRequest base, VariationOptions options, Precision scalar = Precision::Double);
  Case make(std::uint64_t campaignSeed, std::uint64_t index) const override;
  Shrunk shrink(std::uint64_t campaignSeed, std::uint64_t index, const RunRequest& failing, const Fails& fails,
                std::size_t budget) const override;
  std::string describe() const override;
  Departure departure(std::uint64_t campaignSeed, std::uint64_t index) const;
  const RunRequest& base() const { return base_; }

 private:
  RunRequest base_;
  VariationOptions options_;
  Precision scalar_;
};

struct CampaignOptions {
  std::vector<const Property*> properties;
  const CaseSource* source = nullptr;  // nullptr: generated boards
  std::uint64_t count = 100;
  std::uint64_t seed = 1;
  unsigned jobs = 1;
  std::uint64_t shard = 0, shards = 1;  // this run takes the cases k with k % shards == shard
  std::size_t shrinkBudget = 100;       // property checks spent minimising one failure
  // Asked before each case: true stops the campaign (a wall-clock budget lives in the caller).
  std::function<bool()> stop;
  // Called after each case, from the worker threads but never two at once.
  std::function<void(std::uint64_t done, std::uint64_t planned, std::uint64_t failures)> progress;
  // Called as a case starts and as it ends (with its failed properties), from the worker threads
  // but never two at once: a log that says which case a silent shard is on.
  std::function<void(std::uint64_t index)> caseStarted;
  std::function<void(std::uint64_t index, std::uint64_t failed)> caseFinished;
};

// One property on one case.
struct CaseOutcome {
  std::uint64_t index = 0;  // the case
  std::uint64_t seed = 0;   // caseSeed(campaign seed, index)
  int size = 0;
  std::string property;
  bool holds = true;
  std::uint64_t fingerprint = 0;
  // When it does not hold:
  std::string message;  // for the minimal run
  RunRequest minimal;
  Precision scalar = Precision::Double;  // the minimal run's
  std::string departure;                 // a variation's: how the minimal run departs from the user's, in words
  std::size_t shrinkSteps = 0;
  std::optional<double> failedAt = std::nullopt;  // when the minimal run failed, where the property says
  std::string folder;  // where its files are, relative to the campaign's folder (once written)
};

struct CampaignResult {
  std::uint64_t seed = 0, count = 0;
  std::string properties;                     // comma-separated, in the order checked
  std::string cases = "generated";            // CaseSource::describe()
  std::vector<std::uint64_t> shardsIncluded;  // which shards of `shards` this holds
  std::uint64_t shards = 1;
  bool complete = true;               // false: stopped before every case of its shards ran
  std::vector<CaseOutcome> outcomes;  // by case, then property
};

class CampaignError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The case's size: cases cycle through every size from 0 to kMaxSize.
int caseSize(std::uint64_t index);
RunRequest caseRun(std::uint64_t campaignSeed, std::uint64_t index);
// The default source: generateRun(caseSeed(seed, k), caseSize(k)), shrunk by minimise().
const CaseSource& generatedCases();

CampaignResult runCampaign(const CampaignOptions& options);

std::uint64_t failureCount(const CampaignResult& r);
// How many cases the result holds (each checked against every property), and how many its shards
// have: fewer when it stopped early.
std::uint64_t casesChecked(const CampaignResult& r);
std::uint64_t casesPlanned(const CampaignResult& r);
// "seed 7, cases 0..39 of 40, 6 properties: 240 checks, 0 failures, digest 0123456789abcdef": the
// same line for a run and for the merge of its shards.
std::string summaryLine(const CampaignResult& r);
// The digest that line ends with: every outcome and the fingerprint of what each check saw, in
// case order (16 hex digits).
std::string campaignDigest(const CampaignResult& r);

// Writes dir/results.txt (one line per outcome) and, for each failure, a folder with the minimal
// board (board.xml), its key script (keys.txt), its replay log (run.gzlog), what failed
// (failure.txt) and the one-line command that checks it again (command.txt). `gizmo` is how the
// command names the program; `expectFile`, when not empty, is the user's expectation file, which
// that command then checks too. A variation's failure also has departure.txt: how its minimal run
// departs from the user's, in words. Throws CampaignError when dir cannot be written.
void writeCampaign(CampaignResult& r, const std::string& dir, const std::string& gizmo,
                   const std::string& expectFile = "");
// Reads what writeCampaign wrote. Throws CampaignError (naming the file and line) when it is not,
// and when a result that says it is complete lacks a check of its shards or holds one twice, or
// holds a case of another shard: a file cut short or edited, never merged as if whole.
CampaignResult readCampaign(const std::string& dir);
// One result from the shards of one campaign: same seed, count, properties and shard count, no
// shard twice, every shard present. Throws CampaignError otherwise. Folders keep their place
// (each outcome's folder is prefixed with the directory it came from).
CampaignResult mergeCampaigns(const std::vector<std::pair<std::string, CampaignResult>>& parts);

}  // namespace gizmo::verify::fuzz
