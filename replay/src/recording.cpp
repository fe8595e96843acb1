// Recording a run into a replay log (replay.hpp: recordRun, recordHeader).
#include "gizmo/replay/recorder.hpp"
#include "log_views.hpp"

namespace gizmo::replay {
namespace {

using namespace detail;

template <class Real>
RecordResult recordAs(const RunRequest& request, const PrecisionChoice& precision, ChunkSink& sink,
                      const std::vector<std::string>& boardWarnings) {
  std::unique_ptr<GameBoard<Real>> board = prepareRun<Real>(request);
  sink.header(headerBytes(request, precision, *board, boardWarnings));
  Recorder<Real> recorder(sink, *board);
  board->setObserver(&recorder);
  RecordResult result;
  try {
    continueRun(*board, request, 0);
  } catch (const StallError& e) {
    result.completed = false;
    result.error = e.what();
  }
  recorder.finish(result.completed, result.error);
  result.summary = summarize(*board);
  return result;
}

}  // namespace

RecordResult recordRun(const RunRequest& request, const PrecisionChoice& precision, ChunkSink& sink,
                       const std::vector<std::string>& boardWarnings) {
  return withRecordablePrecision(precision,
                                 [&]<class Real>() { return recordAs<Real>(request, precision, sink, boardWarnings); });
}

std::vector<std::uint8_t> recordHeader(const RunRequest& request, const GameBoard<double>& board,
                                       const std::vector<std::string>& boardWarnings,
                                       const std::optional<BranchOrigin>& parent) {
  return headerBytes(request, PrecisionChoice{Precision::Double, 0}, board, boardWarnings, parent);
}

}  // namespace gizmo::replay
