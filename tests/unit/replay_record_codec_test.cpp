// The record encoder and decoder on report sequences written by hand (docs/replay-format.md,
// "The implied friction rule"): what the board reports, the decoder gives back, in order.
#include <gtest/gtest.h>

#include <vector>

#include "gizmo/replay/record_codec.hpp"
#include "support/event_at.hpp"

namespace gizmo::replay {
namespace {

std::vector<Decision<double>> decodeAll(const ByteWriter& written, const PhysicsParams<double>& params) {
  ByteReader in(written.bytes());
  RecordDecoder<double> decoder(in, params, 100);
  decoder.reset(0, {}, 0);
  std::vector<Decision<double>> out;
  while (!decoder.atEnd()) out.push_back(decoder.next());
  return out;
}

// A gizmo started in an instant releases what it held once the instant is over, after the
// instant's last event: the release's rules are then held, and the next event can be a friction
// tick with nothing scheduled or removed between (campaign seed 1796534332, case 5149). Its
// friction rule is still left out and implied, after the earlier rules are written.
TEST(RecordCodec, RulesOfAnEarlierInstantBeforeAFrictionTickAreWrittenAndItsRuleImplied) {
  PhysicsParams<double> params;
  ByteWriter written;
  RecordEncoder<double> encoder(written, params);
  encoder.reset(0, 0);
  const Event<double> friction = test::eventAt(0.01, EventKind::FrictionTick, 1, kNoGizmo, -1, 0);
  const Event<double> hit = test::eventAt(0.005, EventKind::Collision, 2, 3, 0, 1);
  encoder.scheduled(friction);
  encoder.scheduled(hit);
  encoder.executed(hit, EventOutcome<double>{});
  encoder.rule(0.005, ModelRule::ContactEnd, 3, 2);  // the release, once the instant is over
  encoder.rule(0.01, ModelRule::FrictionApplied, 1, kNoGizmo);
  ASSERT_NO_THROW(encoder.executed(friction, EventOutcome<double>{}));
  encoder.flush();

  const std::vector<Decision<double>> d = decodeAll(written, params);
  ASSERT_EQ(d.size(), 6u);
  EXPECT_EQ(d[2].type, DecisionType::Executed);
  EXPECT_EQ(d[2].event.kind, EventKind::Collision);
  EXPECT_EQ(d[3].type, DecisionType::Rule);
  EXPECT_EQ(d[3].rule, ModelRule::ContactEnd);
  EXPECT_EQ(d[3].time, 0.005);
  EXPECT_EQ(d[4].type, DecisionType::Executed);
  EXPECT_EQ(d[4].event.kind, EventKind::FrictionTick);
  EXPECT_EQ(d[5].type, DecisionType::Rule);
  EXPECT_EQ(d[5].rule, ModelRule::FrictionApplied);
  EXPECT_EQ(d[5].gizmo, 1);
  EXPECT_EQ(d[5].time, 0.01);
}

}  // namespace
}  // namespace gizmo::replay
