#include "instantiate.hpp"

GIZMO_INSTANTIATE_CORE(Float128)
