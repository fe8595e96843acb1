#include "trace_run_impl.hpp"

namespace gizmo::verify {
GIZMO_INSTANTIATE_TRACE_RUN(double)
}
