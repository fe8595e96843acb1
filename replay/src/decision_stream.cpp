// Walking a log's decisions in order, decoded from its chunks (replay.hpp: DecisionStream).
#include <optional>

#include "log_views.hpp"

namespace gizmo::replay {

class DecisionStream::Source {
 public:
  virtual ~Source() = default;
  virtual std::optional<DecisionView> next() = 0;
};

namespace {

using namespace detail;

template <class Real>
class StreamAs final : public DecisionStream::Source {
 public:
  StreamAs(const OpenedLog& log, double fromTime) : log_(log), params_(paramsOf<Real>(log)) {
    const std::vector<ChunkEntry>& chunks = log.reader.chunks();
    while (chunk_ + 1 < chunks.size() && chunks[chunk_ + 1].time <= fromTime) ++chunk_;
  }
  std::optional<DecisionView> next() override {
    while (!records_ || records_->atEnd()) {
      if (chunk_ >= log_.reader.chunks().size()) return std::nullopt;
      payload_ = log_.reader.chunkPayload(chunk_++);
      opened_ = openChunk<Real>(payload_);
      records_.emplace(payload_, opened_, params_, maxQueued(log_));
      index_ = opened_.preamble.decisionsDone;
      events_ = opened_.preamble.eventsDone;
    }
    const Decision<Real> d = records_->next();
    DecisionView v = viewOf(d, index_++, events_, log_.gizmoNames);
    if (d.type == DecisionType::Executed) ++events_;
    return v;
  }

 private:
  const OpenedLog& log_;
  PhysicsParams<Real> params_;
  std::size_t chunk_ = 0;
  std::vector<std::uint8_t> payload_;
  OpenedChunk<Real> opened_;
  std::optional<ChunkRecords<Real>> records_;
  std::uint64_t index_ = 0, events_ = 0;
};

}  // namespace

DecisionStream::DecisionStream(const OpenedLog& log, double fromTime)
    : source_(detail::withLogScalar(log, [&]<class Real>() -> std::unique_ptr<Source> {
        return std::make_unique<StreamAs<Real>>(log, fromTime);
      })) {}
DecisionStream::~DecisionStream() = default;
DecisionStream::DecisionStream(DecisionStream&&) noexcept = default;
std::optional<DecisionView> DecisionStream::next() { return source_->next(); }

}  // namespace gizmo::replay
