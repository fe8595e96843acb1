// `gizmo diff`: the first decision where two logs part, with the decisions around it.
#include <cstdio>
#include <iostream>

#include "board_input.hpp"
#include "log_commands.hpp"
#include "log_view.hpp"

namespace gizmo::cli {

int diffCommand(const DiffOptions& o) {
  int code = kExitOk;
  const std::optional<replay::OpenedLog> a = openLogFor("diff", o.first, code);
  if (!a) return code;
  const std::optional<replay::OpenedLog> b = openLogFor("diff", o.second, code);
  if (!b) return code;
  replay::DiffReport r;
  try {
    r = replay::diffLogs(*a, *b, std::size_t(o.context), o.summary);
  } catch (const replay::BranchError& e) {
    std::cerr << "gizmo diff: " << o.first << ", " << o.second << ": " << e.what() << '\n';
    return kExitBadInput;
  } catch (const std::exception& e) {
    std::cerr << "gizmo diff: " << e.what() << '\n';
    return kExitBadInput;
  }
  const int exit = r.parted ? kExitCheckFailed : kExitOk;
  if (o.json) {
    nlohmann::ordered_json j{{"parted", r.parted},
                             {"same_scalar", r.sameScalar},
                             {"matched", r.matched},
                             {"first_decision", r.firstDecision},
                             {"max_time_difference", r.maxTimeDifference},
                             {"max_position_difference", r.maxPositionDifference},
                             {"notes", r.notes}};
    if (r.parted) {
      j["where"] = r.where;
      j["first"] = r.first ? decisionJson(*r.first, a->gizmoNames) : nlohmann::ordered_json();
      j["second"] = r.second ? decisionJson(*r.second, b->gizmoNames) : nlohmann::ordered_json();
    }
    if (o.summary) {
      nlohmann::ordered_json counts;
      for (const auto& [kind, n] : r.counts) counts[kind] = {n.first, n.second};
      j["counts"] = counts;
    }
    std::cout << j.dump(2) << '\n';
    std::cout.flush();
    return finishWithCutOffLogs("diff", exit, {&*a, &*b}, {o.first, o.second});
  }
  for (const std::string& n : r.notes) std::printf("note: %s\n", n.c_str());
  if (!r.parted) {
    std::printf("alike: all %llu decisions%s%s\n", static_cast<unsigned long long>(r.matched),
                r.firstDecision ? (" from decision " + std::to_string(r.firstDecision)).c_str() : "",
                r.sameScalar ? " are identical" : " are the same decisions");
  } else {
    std::printf("the logs part at decision %llu: %s\n", static_cast<unsigned long long>(r.firstDecision + r.matched),
                r.where.c_str());
    for (const replay::DecisionView& d : r.before)
      std::printf("  both    %s\n", decisionLine(d, a->gizmoNames, false).c_str());
    std::printf("> first   %s\n", r.first ? decisionLine(*r.first, a->gizmoNames, true).c_str() : "(ends)");
    std::printf("> second  %s\n", r.second ? decisionLine(*r.second, b->gizmoNames, true).c_str() : "(ends)");
    for (const replay::DecisionView& d : r.afterFirst)
      std::printf("  first   %s\n", decisionLine(d, a->gizmoNames, false).c_str());
    for (const replay::DecisionView& d : r.afterSecond)
      std::printf("  second  %s\n", decisionLine(d, b->gizmoNames, false).c_str());
  }
  if (!r.sameScalar)
    std::printf("before that: event times differ by at most %.3g s, ball positions by at most %.3g L\n",
                r.maxTimeDifference, r.maxPositionDifference);
  if (o.summary) {
    std::printf("%-28s %12s %12s\n", "decisions", "first", "second");
    for (const auto& [kind, n] : r.counts)
      std::printf("%-28s %12llu %12llu\n", kind.c_str(), static_cast<unsigned long long>(n.first),
                  static_cast<unsigned long long>(n.second));
  }
  std::fflush(stdout);
  return finishWithCutOffLogs("diff", exit, {&*a, &*b}, {o.first, o.second});
}

}  // namespace gizmo::cli
