#pragma once
// rapidcheck's view of the fuzzer's generated runs. Generation and shrinking are the library's
// (verify/fuzz: the same code `gizmo fuzz` uses); rapidcheck supplies the seed and the size of
// each case, searches the shrinks, and prints the counterexample through showValue below, which
// gives every number exactly (rapidcheck's own printing keeps 6 digits).
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <ostream>
#include <string>

#include "gizmo/core/run/run.hpp"
#include "gizmo/verify/fuzz/properties.hpp"
#include "gizmo/verify/fuzz/run_description.hpp"
#include "gizmo/verify/fuzz/run_generator.hpp"
#include "gizmo/verify/fuzz/run_shrinker.hpp"

namespace gizmo {

// Found by rapidcheck through argument-dependent lookup.
inline void showValue(const RunRequest& run, std::ostream& os) { os << "\n" << verify::fuzz::describeRun(run); }

namespace test {

inline rc::Gen<RunRequest> arbitraryRun() {
  return rc::Gen<RunRequest>([](const rc::Random& random, int size) {
    rc::Random r = random;
    const std::uint64_t seed = r.next();
    return rc::shrinkable::shrinkRecur(verify::fuzz::generateRun(seed, size), [](const RunRequest& run) {
      return rc::seq::fromContainer(verify::fuzz::shrinkCandidates(run));
    });
  });
}

// Fails the current rapidcheck case when the named property does not hold, saying why and which
// rapidcheck seed reproduces it (rapidcheck shows the shrunk run itself).
inline void requireProperty(const char* name, const RunRequest& run) {
  const verify::fuzz::Property* p = verify::fuzz::findProperty(name);
  RC_ASSERT(p != nullptr);
  const verify::fuzz::PropertyResult r = p->check(run, Precision::Double);
  if (!r.holds)
    RC_FAIL(std::string(name) + " does not hold: " + r.message + "\n(rapidcheck seed " +
            std::to_string(rc::detail::configuration().testParams.seed) +
            "; run again with RC_PARAMS=\"seed=" + std::to_string(rc::detail::configuration().testParams.seed) + "\")");
}

}  // namespace test
}  // namespace gizmo
