#pragma once
// How the log commands (replay, dump, diff) print a decision and a state: one readable line, or
// one JSON object. Exact values appear as hex floats next to their decimal rounding.
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <string>

#include "gizmo/replay/replay.hpp"

namespace gizmo::cli {

std::string decisionLine(const replay::DecisionView& d, const std::vector<std::string>& names, bool exact);
nlohmann::ordered_json decisionJson(const replay::DecisionView& d, const std::vector<std::string>& names);

void printState(const std::string& label, const replay::StateView& s);
nlohmann::ordered_json stateJson(const replay::StateView& s);

// The gizmos a decision names (for filters).
bool involves(const replay::DecisionView& d, GizmoId id);
// The kind a decision has for --kind: an event kind for event decisions ("collision"), else its
// type ("trigger", "rule", "tick", …); a rule also answers to its own name ("friction").
bool hasKind(const replay::DecisionView& d, std::string_view kind);
bool isKindName(std::string_view kind);

// A log starts with its magic; anything else is taken for a board file.
bool isLogFile(const std::string& path);

// Opens a log for a command; on failure prints why and returns nullopt with exitCode set.
std::optional<replay::OpenedLog> openLogFor(const std::string& command, const std::string& path, int& exitCode);

// A cut-off log is read as far as it goes, and the command's work is done on that part; then it
// says where the log stops and exits 2 (bad input), unless it already failed a check.
int finishWithCutOffLogs(const std::string& command, int code, std::initializer_list<const replay::OpenedLog*> logs,
                         std::initializer_list<std::string> paths);

}  // namespace gizmo::cli
