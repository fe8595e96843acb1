// The certification report as text (for people) and as JSON (for tools). Times are printed
// exactly as hex floats, with the decimal value beside them.
#include <cmath>
#include <cstdio>
#include <ostream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "gizmo/verify/certify.hpp"

namespace gizmo::verify {

namespace {

std::string both(const ExactBound& b) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.17g", b.value);
  return b.hex + " (" + buf + ")";
}

nlohmann::ordered_json boundJson(const ExactBound& b) {
  return nlohmann::ordered_json{
      {"hex", b.hex},
      {"value", std::isfinite(b.value) ? nlohmann::ordered_json(b.value) : nlohmann::ordered_json(b.hex)}};
}

nlohmann::ordered_json eventJson(const EventRef& e) {
  return nlohmann::ordered_json{{"kind", std::string(eventKindName(e.kind))},
                                {"a", e.a},
                                {"b", e.b},
                                {"feature", e.feature},
                                {"description", e.description}};
}

std::string rungName(long bits) {
  if (bits == 0) return "exact rationals";
  return bits == 53 ? "double intervals" : "mpfi:" + std::to_string(bits);
}

// "2^-512": the resolution below which the top rung calls two times a tie it could not prove.
std::string tieResolution(const CertifyReport& r) {
  const long top = r.rungBits.size() >= 2 ? r.rungBits[r.rungBits.size() - 2] : 53;
  return "2^-" + std::to_string(top / 2);
}

}  // namespace

void printCertifyReport(std::ostream& out, const CertifyReport& r) {
  out << "certified decisions (" << r.model << "): " << r.certified() << " of " << r.decisions << "\n";
  for (std::size_t i = 0; i < r.rungBits.size(); ++i)
    out << "  certified with " << rungName(r.rungBits[i]) << ": " << r.certifiedAtRung[i] << "\n";
  for (int k = 0; k < kUncertifiedReasonCount; ++k)
    out << "  not certified, " << uncertifiedReasonName(UncertifiedReason(k)) << ": "
        << r.uncertifiedByReason[std::size_t(k)] << "\n";
  std::size_t tieOrderBroken = 0;
  for (const TieDecision& t : r.ties) tieOrderBroken += t.orderFollowed ? 0 : 1;
  out << "  ties: " << r.ties.size() << " (proven exact: " << r.provenTies() << ", within " << tieResolution(r)
      << " only: " << r.ties.size() - r.provenTies() << "; tie order not followed: " << tieOrderBroken << ")\n";
  out << "  wrong decisions: " << r.wrong.size() << "\n";
  for (const TieDecision& t : r.ties) {
    out << "tie at event " << t.eventIndex << ", t = " << both(t.time) << ": " << t.executed.description << " and "
        << t.other.description;
    for (const EventRef& e : t.alsoTied) out << " and " << e.description;
    if (t.proven) out << ", proven exactly equal; ";
    else out << " within " << both(t.within) << " (not proven exact); ";
    out << (t.orderFollowed ? "documented tie order followed" : "documented tie order NOT followed") << "\n";
  }
  for (const WrongDecision& w : r.wrong) out << wrongDecisionLine(w) << "\n";
}

std::string wrongDecisionLine(const WrongDecision& w) {
  std::ostringstream out;
  out << "wrong decision at event " << w.eventIndex << ", t = " << both(w.time) << ": ran " << w.executed.description
      << ", but " << w.shouldHaveComeFirst.description << " should have come first, by at least " << both(w.byAtLeast)
      << " and at most " << both(w.byAtMost) << " s [" << w.explanation << "; proven with " << rungName(w.rungBits)
      << "]";
  return out.str();
}

namespace {
// "swinging flipper" → "swinging_flipper": JSON keys in one style throughout.
std::string jsonKey(std::string name) {
  for (char& c : name)
    if (c == ' ') c = '_';
  return name;
}
}  // namespace

std::string certifyReportJson(const CertifyReport& r) {
  nlohmann::ordered_json j;
  j["model"] = r.model;
  j["decisions"] = r.decisions;
  j["certified"] = r.certified();
  nlohmann::ordered_json rungs = nlohmann::ordered_json::array();
  for (std::size_t i = 0; i < r.rungBits.size(); ++i)
    rungs.push_back({{"rung", rungName(r.rungBits[i])}, {"bits", r.rungBits[i]}, {"certified", r.certifiedAtRung[i]}});
  j["rungs"] = rungs;
  nlohmann::ordered_json reasons = nlohmann::ordered_json::object();
  for (int k = 0; k < kUncertifiedReasonCount; ++k)
    reasons[jsonKey(uncertifiedReasonName(UncertifiedReason(k)))] = r.uncertifiedByReason[std::size_t(k)];
  j["not_certified"] = reasons;
  j["ties_proven"] = r.provenTies();
  nlohmann::ordered_json ties = nlohmann::ordered_json::array();
  for (const TieDecision& t : r.ties) {
    nlohmann::ordered_json also = nlohmann::ordered_json::array();
    for (const EventRef& e : t.alsoTied) also.push_back(eventJson(e));
    ties.push_back({{"event", t.eventIndex},
                    {"time", boundJson(t.time)},
                    {"executed", eventJson(t.executed)},
                    {"other", eventJson(t.other)},
                    {"also_tied", also},
                    {"proven", t.proven},
                    {"within", boundJson(t.within)},
                    {"order_followed", t.orderFollowed}});
  }
  j["ties"] = ties;
  nlohmann::ordered_json wrong = nlohmann::ordered_json::array();
  for (const WrongDecision& w : r.wrong)
    wrong.push_back({{"event", w.eventIndex},
                     {"time", boundJson(w.time)},
                     {"executed", eventJson(w.executed)},
                     {"should_have_come_first", eventJson(w.shouldHaveComeFirst)},
                     {"by_at_least", boundJson(w.byAtLeast)},
                     {"by_at_most", boundJson(w.byAtMost)},
                     {"explanation", w.explanation},
                     {"proven_with_bits", w.rungBits}});
  j["wrong"] = wrong;
  return j.dump(2);
}

}  // namespace gizmo::verify
