#pragma once
// Expectations that a user writes about a board of their own, one to a line of a small text file
// (docs/fuzzing.md, "Expectations"), and the check of a run against them. Each kind has a name,
// a precise meaning, a located error for a malformed line, and a failure message that names the
// ball, the board time and the place:
//
//   reaches ABSORBER within SECONDS [ball NAME]   every ball (or NAME) is captured by ABSORBER
//                                                 within SECONDS of entering play
//   avoids X0 Y0 X1 Y1 [ball NAME]                no ball's centre ever enters the rectangle
//   rests-at-most SECONDS [ball NAME]             no ball outside an absorber stays slower than
//                                                 kRestSpeed for longer than SECONDS
//   hit GIZMO at-least N within SECONDS           GIZMO is struck by balls at least N times in
//                                                 the first SECONDS of the run
//   stays-on-board [ball NAME]                    no ball is taken out of play (a sink) or has
//                                                 its centre off the 20 × 20 board
#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "gizmo/core/run/run.hpp"
#include "gizmo/verify/fuzz/properties.hpp"

namespace gizmo::verify::fuzz {

enum class ExpectationKind { Reaches, Avoids, RestsAtMost, Hit, StaysOnBoard };
std::string_view expectationKindName(ExpectationKind kind);

// Slower than this (L/s) a ball counts as resting: a hundredth of a cell per second.
inline constexpr double kRestSpeed = 0.01;

struct Expectation {
  ExpectationKind kind = ExpectationKind::StaysOnBoard;
  std::string ball;                       // the ball it is about; empty for every ball
  std::string gizmo;                      // Reaches: the absorber; Hit: the gizmo struck
  double seconds = 0;                     // Reaches, Hit: the time allowed; RestsAtMost: the longest rest
  long count = 1;                         // Hit: the fewest hits
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // Avoids: the rectangle, x0 < x1 and y0 < y1
  std::string source;                     // "FILE:LINE", for messages
};

// A malformed line, or a name the board does not have: "FILE:LINE: what is wrong".
class ExpectationError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// `fileName` only names the text in messages. Blank lines and `#` comments are skipped.
std::vector<Expectation> parseExpectations(std::string_view text, const std::string& fileName);
std::vector<Expectation> readExpectationFile(const std::string& path);

// The board time a run must reach to decide every expectation: the longest time one allows.
double expectationHorizon(const std::vector<Expectation>& expectations);

struct ExpectationFailure {
  std::size_t expectation = 0;  // its index
  double time = 0;              // the board time at which it was seen broken
  std::string message;          // the expectation's source, the ball, the time and the place
};

// Runs the request in double, for its duration or the horizon if that is longer, and returns the
// first failure of each expectation broken (none: all hold). A ball or gizmo the board does not
// have, or a `reaches` of a gizmo that is no absorber, is an ExpectationError.
std::vector<ExpectationFailure> checkExpectations(RunRequest request, const std::vector<Expectation>& expectations);

// Throws the ExpectationError checkExpectations would for a name the board lacks, without running.
void checkExpectationNames(const RunRequest& request, const std::vector<Expectation>& expectations);

// The expectations as one more property, "expectations", that a campaign checks beside the six:
// it holds when every expectation holds, and otherwise says the first one broken (by board time)
// and how many others are. A name the board lacks fails it too, with the ExpectationError's text.
Property expectationsProperty(std::vector<Expectation> expectations);
inline constexpr std::string_view kExpectationsPropertyName = "expectations";

}  // namespace gizmo::verify::fuzz
