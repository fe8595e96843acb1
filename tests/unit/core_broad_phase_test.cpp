// The broad phase's id set, which lists the candidates of a ball in id order without repeats.
#include <gtest/gtest.h>

#include <vector>

#include "gizmo/core/board/id_set.hpp"

namespace gizmo {
namespace {

TEST(IdSet, ListsItsMembersOnceInAscendingOrderAndEmpties) {
  IdSet set;
  set.reset(300);
  for (GizmoId id : {200, 3, 64, 63, 3, 299, 0, 64, 127, 128}) set.insert(id);
  std::vector<GizmoId> out{-7};  // drained members are appended
  set.drainInto(out);
  EXPECT_EQ(out, (std::vector<GizmoId>{-7, 0, 3, 63, 64, 127, 128, 200, 299}));
  out.clear();
  set.drainInto(out);
  EXPECT_TRUE(out.empty());
  set.insert(5);
  set.drainInto(out);
  EXPECT_EQ(out, (std::vector<GizmoId>{5}));
}

}  // namespace
}  // namespace gizmo
