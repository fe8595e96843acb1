// `gizmo dump`: a log's decisions, one line (or one JSON object) each, optionally filtered.
#include <cmath>
#include <cstdio>
#include <iostream>

#include "board_input.hpp"
#include "log_commands.hpp"
#include "log_view.hpp"

namespace gizmo::cli {

int dumpCommand(const DumpOptions& o) {
  if (!o.kind.empty() && !isKindName(o.kind)) {
    std::cerr << "gizmo dump: unknown kind '" << o.kind
              << "' (an event kind such as collision or friction-tick, a decision type such as scheduled, "
                 "executed, trigger, rule, tick, or a model rule such as friction)\n";
    return kExitBadInput;
  }
  for (const std::optional<double>& t : {o.from, o.to})
    if (t && !std::isfinite(*t)) {
      std::cerr << "gizmo dump: --from and --to must be numbers of seconds\n";
      return kExitBadInput;
    }
  int code = kExitOk;
  const std::optional<replay::OpenedLog> log = openLogFor("dump", o.log, code);
  if (!log) return code;
  std::optional<GizmoId> gizmo;
  if (!o.gizmo.empty()) {
    for (std::size_t i = 0; i < log->gizmoNames.size(); ++i)
      if (log->gizmoNames[i] == o.gizmo) gizmo = GizmoId(i);
    if (!gizmo) {
      std::cerr << "gizmo dump: the log's board has no gizmo named '" << o.gizmo << "'\n";
      return kExitBadInput;
    }
  }
  try {
    replay::DecisionStream stream(*log, o.from.value_or(-1));
    std::string out;
    while (const std::optional<replay::DecisionView> d = stream.next()) {
      if (o.from && d->time.value < *o.from) continue;
      if (o.to && d->time.value > *o.to) break;
      if (!o.kind.empty() && !hasKind(*d, o.kind)) continue;
      if (gizmo && !involves(*d, *gizmo)) continue;
      out = o.json ? decisionJson(*d, log->gizmoNames).dump() : decisionLine(*d, log->gizmoNames, o.exact);
      std::fputs(out.c_str(), stdout);
      std::fputc('\n', stdout);
    }
  } catch (const std::exception& e) {
    std::fflush(stdout);
    std::cerr << "gizmo dump: " << o.log << ": " << e.what() << '\n';
    return kExitBadInput;
  }
  std::fflush(stdout);
  return finishWithCutOffLogs("dump", kExitOk, {&*log}, {o.log});
}

}  // namespace gizmo::cli
