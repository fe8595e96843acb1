// libFuzzer target for the simulator itself: the bytes are a small run (simulation_input.hpp),
// simulated in double under every invariant of InvariantChecker (no-tunnelling, energy,
// event-queue); a violation, or a run that stops with an error, aborts after printing the run
// exactly, which libFuzzer and the corpus runner report as a crash. Inputs that describe no run
// the target takes return at once: the readers have targets of their own, and a big or long run
// would cost seconds per input. The seed corpus is made from the fixtures
// (tests/fuzz/simulation_corpus.cmake).
//
// To reproduce a crash: `simulation_corpus_run FILE` in any build, or scripts/simulation-fuzz-check.sh
// GIZMO FILE, which splits FILE into a board and a key script and checks them with `gizmo fuzz --check`.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <iterator>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "gizmo/verify/fuzz/invariants.hpp"
#include "gizmo/verify/fuzz/run_description.hpp"
#include "simulation_input.hpp"

namespace fz = gizmo::verify::fuzz;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::optional<gizmo::RunRequest> run =
      gizmo::fuzzing::simulation::readRun(std::string_view(reinterpret_cast<const char*>(data), size));
  if (!run) return 0;
  const std::vector<fz::Invariant> all(std::begin(fz::kAllInvariants), std::end(fz::kAllInvariants));
  const fz::InvariantRun result = fz::checkInvariants<double>(*run, all);
  if (result.violations.empty()) return 0;
  for (const fz::Violation& v : result.violations)
    std::fprintf(stderr, "invariant %s broken: %s\n", std::string(fz::invariantName(v.invariant)).c_str(),
                 v.message.c_str());
  std::fprintf(stderr, "after %llu events; the run:\n%s\n", static_cast<unsigned long long>(result.events),
               fz::describeRun(*run).c_str());
  std::abort();
}
