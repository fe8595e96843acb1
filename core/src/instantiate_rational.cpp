#include "instantiate.hpp"

GIZMO_INSTANTIATE_CORE(Rational)
