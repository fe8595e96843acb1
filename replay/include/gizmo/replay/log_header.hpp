#pragma once
// The header frame: everything needed to run the recorded run again — the board in canonical
// text with its hash, the motion model, the scalar, every simulation parameter, the duration
// and the key input.
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "gizmo/core/run/run.hpp"
#include "gizmo/replay/bytes.hpp"
#include "gizmo/replay/format_error.hpp"
#include "gizmo/replay/log_format.hpp"
#include "gizmo/replay/scalar_codec.hpp"

namespace gizmo::replay {

// Where a branch log (format version 5) was taken from: its parent log, named by the checksum64
// of the parent file's bytes, and the branch point, the number of the parent's events before the
// branch takes over.
struct BranchOrigin {
  std::uint64_t parentDigest = 0;
  std::uint64_t event = 0;

  bool operator==(const BranchOrigin&) const = default;
};

struct LogHeader {
  std::string toolkit;    // the gizmo version that wrote the log
  std::string precision;  // as requested ("double", "mpfr:256"): selects the scalar again
  std::string scalar;     // as computed ("mpfr:261"): checked when the log is read back
  std::string format;     // the scalar's binary format ("binary64", "x87-extended80"): likewise
  MotionModel model = MotionModel::Ballistic;
  double maxTick = 0.05;
  double duration = 0;
  std::vector<TimedKey> keys;
  std::string board;            // canonical text form (io::writeTextBoard)
  std::uint64_t boardHash = 0;  // checksum64 of the board text
  // What the board reader said about the file the board came from (io::format of each warning):
  // empty when it was read as written. Since format version 3.
  std::vector<std::string> boardWarnings;
  std::vector<std::uint8_t> params;  // PhysicsParams in the scalar's exact encoding (paramBytes)
  // A branch log's parent (format version 5 only); absent in every other log.
  std::optional<BranchOrigin> parent;
};

// The header of a run about to be recorded in scalar `precision`.
LogHeader headerFor(const RunRequest& request, const std::string& precision, const std::string& scalar,
                    const std::string& format, std::vector<std::uint8_t> params);
std::vector<std::uint8_t> encodeHeader(const LogHeader& h);
// The payload of a log of format `version`: a branch log's (version 5) ends with its parent.
LogHeader decodeHeader(std::span<const std::uint8_t> payload,
                       std::uint16_t version = kFormatVersion);  // throws FormatError
// The run the header describes; throws FormatError when the embedded board does not read back
// or does not match its hash.
RunRequest requestOf(const LogHeader& h);

template <class Real>
std::vector<std::uint8_t> paramBytes(const PhysicsParams<Real>& p) {
  ByteWriter w;
  const Real zero(0);
  w.u8(static_cast<std::uint8_t>(p.model));
  for (const Real* x : {&p.gravity, &p.mu, &p.mu2, &p.maxTick, &p.frictionStep, &p.restSpeed}) writeScalar(w, *x, zero);
  w.svarint(p.pinchLimit);
  const auto b = w.bytes();
  return {b.begin(), b.end()};
}

template <class Real>
PhysicsParams<Real> readParams(std::span<const std::uint8_t> bytes) {
  ByteReader r(bytes);
  PhysicsParams<Real> p;
  const Real zero(0);
  const std::uint8_t model = r.u8();
  if (model > 1) throw FormatError("header: unknown motion model", 0);
  p.model = static_cast<MotionModel>(model);
  for (Real* x : {&p.gravity, &p.mu, &p.mu2, &p.maxTick, &p.frictionStep, &p.restSpeed}) *x = readScalar<Real>(r, zero);
  const std::int64_t pinch = r.svarint();
  if (pinch < 0 || pinch > INT32_MAX) throw FormatError("header: pinch limit out of range", r.position());
  p.pinchLimit = static_cast<std::int32_t>(pinch);
  if (!r.atEnd()) throw FormatError("header: bytes after the parameters", r.position());
  return p;
}

}  // namespace gizmo::replay
