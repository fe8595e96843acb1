#pragma once
// Certified decisions (docs/verification.md, "Certified decisions"): a double run re-simulated
// from its log, and every executed event proven, with interval arithmetic, to have been the
// earliest for the state the run had just before it. Decisions the double intervals cannot
// settle climb a ladder of MPFI precisions; events that stay overlapping are compared exactly
// where their gaps are polynomials (a proven tie), and what is still unsettled at the top is a
// tie within the top rung's resolution.
#include <array>
#include <cstdint>
#include <iosfwd>
#include <stdexcept>
#include <string>
#include <vector>

#include "gizmo/core/board/event.hpp"
#include "gizmo/replay/replay.hpp"

namespace gizmo::verify {

struct CertifyOptions {
  // The MPFI precisions tried, in order, after the double intervals.
  std::vector<long> mpfiBits{128, 256, 512, 1024};
  // Stop after this many executed events (0: the whole log). For looking at the start of a
  // long run.
  std::uint64_t maxEvents = 0;
};

// Why a decision is neither certified nor proven wrong nor a tie: the search ran out of
// subdivisions at every rung without a narrow overlap, with a swinging flipper's or a turning
// spinner's side or tip among the events left overlapping (their gaps are not polynomials: no
// exact step), or not.
enum class UncertifiedReason : std::uint8_t {
  SwingingFlipper,
  Undecided,
  TurningSpinner,
};
inline constexpr int kUncertifiedReasonCount = 3;
std::string uncertifiedReasonName(UncertifiedReason r);

// An event of the run, or one that the certifier found, as plain data.
struct EventRef {
  EventKind kind = EventKind::EndOfTick;
  GizmoId a = kNoGizmo, b = kNoGizmo;
  std::int32_t feature = -1;
  std::string description;  // e.g. "collision OuterWalls/B feature 2"
};

// A time bound printed exactly (hex float) and in decimal.
struct ExactBound {
  double value = 0;
  std::string hex;
};
ExactBound exactBound(double v);

struct WrongDecision {
  std::uint64_t eventIndex = 0;  // events executed before this one
  ExactBound time;               // when the run executed it
  EventRef executed;
  EventRef shouldHaveComeFirst;
  // The other event came first by at least `byAtLeast` and at most `byAtMost` seconds (a claimed
  // collision that never happens before the next scheduled event has byAtMost = +inf).
  ExactBound byAtLeast, byAtMost;
  std::string explanation;
  long rungBits = 53;  // the precision that proved it (53: the double intervals; 0: exact rationals)
};

struct TieDecision {
  std::uint64_t eventIndex = 0;
  ExactBound time;
  EventRef executed, other;
  // Proven: the times are equal exactly (a common root of their gap polynomials, or a scheduled
  // time that is a root), `within` is 0 and `alsoTied` lists any further events at that instant.
  // Otherwise both times lie in one window of width `within` (seconds), below the top rung's
  // resolution (the gaps involved are not all polynomials, or a root could not be isolated).
  bool proven = false;
  ExactBound within;
  std::vector<EventRef> alsoTied;
  bool orderFollowed = true;  // the run ran the executed event first in the documented tie order (runsBefore)
};

struct UncertifiedDecision {
  std::uint64_t eventIndex = 0;
  ExactBound time;
  EventRef executed;
  UncertifiedReason reason = UncertifiedReason::Undecided;
  EventRef other;     // the rival that could not be separated (or the moving arm)
  ExactBound window;  // Undecided: both may lie in a window this wide (inf: no bound found)
};

struct CertifyReport {
  std::string model;  // classic or ballistic
  std::uint64_t decisions = 0;
  // Certified at each rung: [0] the double intervals, then one per CertifyOptions::mpfiBits, then
  // the exact step (bits 0: two roots closer than the top rung could part, ordered exactly).
  std::vector<long> rungBits;
  std::vector<std::uint64_t> certifiedAtRung;
  std::array<std::uint64_t, kUncertifiedReasonCount> uncertifiedByReason{};
  std::vector<UncertifiedDecision> uncertified;  // the first 100 of them, for looking at
  std::vector<TieDecision> ties;
  std::vector<WrongDecision> wrong;

  std::uint64_t certified() const;
  std::uint64_t provenTies() const;
  bool allCertified() const { return certified() == decisions; }
};

// Refused: a log that is not of a double run (the certificate takes the run's doubles as its
// exact input).
class CertifyError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Re-simulates the log's run (double) and certifies each executed event.
CertifyReport certifyLog(const replay::OpenedLog& log, const CertifyOptions& options = {});
// The same for a run described directly (tests, benchmarks).
CertifyReport certifyRun(const RunRequest& request, const CertifyOptions& options = {});

// The report as text (one line per count, one paragraph per wrong decision) and as JSON.
void printCertifyReport(std::ostream& out, const CertifyReport& report);
std::string certifyReportJson(const CertifyReport& report);
// One wrong decision explained, on one line (as the text report prints it).
std::string wrongDecisionLine(const WrongDecision& wrong);

}  // namespace gizmo::verify
