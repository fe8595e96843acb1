#pragma once
// A certification report as `gizmo verify` prints it: the message of a failed expectation.
#include <sstream>
#include <string>

#include "gizmo/verify/certify.hpp"

namespace gizmo::test {

inline std::string describe(const verify::CertifyReport& r) {
  std::ostringstream out;
  verify::printCertifyReport(out, r);
  return out.str();
}

}  // namespace gizmo::test
