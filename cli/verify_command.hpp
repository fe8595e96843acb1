#pragma once
// `gizmo verify`: a board at every rung of the precision ladder, compared with a reference run;
// or, with --certify, a recorded run checked decision by decision.
#include <cstddef>
#include <string>

#include "run_options.hpp"

namespace gizmo::cli {

struct VerifyOptions {
  RunOptions run;          // run.board is a board, or a log with --certify
  std::string precisions;  // comma-separated; empty: the default ladder
  std::string reference;   // empty: rational where the scene allows, else mpfr:256
  bool certify = false;
  std::size_t exactDigits = 20000;  // budget of an exact run (verify::LadderOptions::exactDigits)
};
int verifyCommand(const VerifyOptions& options);

}  // namespace gizmo::cli
