#include "instantiate.hpp"

GIZMO_INSTANTIATE_CORE(long double)
