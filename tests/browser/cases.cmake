# The browser checks, shared by tests/browser/CMakeLists.txt and tests/browser/run.sh: each is a
# name and the player_seek.cmake settings it runs with.
set(GIZMO_BROWSER_FIXTURES ${CMAKE_CURRENT_LIST_DIR}/../../fixtures)
# The spec's board with the flipper key script, every path piece kept: the ball is drawn at
# exactly the state the log records.
gizmo_browser_test(spec_example_collision
  BOARD=${GIZMO_BROWSER_FIXTURES}/boards/spec-example.txt KEYS=${GIZMO_BROWSER_FIXTURES}/keys/flippers.keys
  TIME=6 PICK=5 TOLERANCE=0)
# The same run at the default tolerance (10^-3 L), later on: the thinned path stays that close.
gizmo_browser_test(spec_example_thinned
  BOARD=${GIZMO_BROWSER_FIXTURES}/boards/spec-example.txt KEYS=${GIZMO_BROWSER_FIXTURES}/keys/flippers.keys
  TIME=6 PICK=9 WITHIN=0.001)
# Two balls under gravity with every path piece kept: both are drawn exactly, the one the
# collision did not touch at its position evaluated on its parabola.
gizmo_browser_test(two_balls_every_piece
  BOARD=${GIZMO_BROWSER_FIXTURES}/boards/verify/chaotic-bumpers.txt TIME=4 PICK=7 TOLERANCE=0)
# The classic model (straight steps at every event, rebuilt by stepping as the board does).
gizmo_browser_test(classic_model
  BOARD=${GIZMO_BROWSER_FIXTURES}/boards/spec-example.txt TIME=6 PICK=5 TOLERANCE=0 MODEL=classic)
# Our run against Box2D's path at 1/240 s (gizmo crosscheck --path-out, gizmo render --compare):
# every path sample kept, Box2D's ball drawn where the path file has it, and the parting marked.
gizmo_browser_test(box2d_overlay
  BOARD=${GIZMO_BROWSER_FIXTURES}/boards/spec-example.txt KEYS=${GIZMO_BROWSER_FIXTURES}/keys/flippers.keys
  TIME=6 PICK=5 TOLERANCE=0 COMPARE_DT=1/240 COMPARE_SAMPLE=300)
# Spawners add balls as the run goes: each is drawn from the event that spawned it on, and not
# before (the balls drawn are exactly the log's).
gizmo_browser_test(spawned_balls
  BOARD=${GIZMO_BROWSER_FIXTURES}/boards/gizmos/spawner.txt TIME=4 PICK=30 TOLERANCE=0)
# A branch log (gizmo record --from) taken mid-tick with a flipper raised: drawn from its first
# keyframe on, with its events numbered as in its parent, each ball exactly where the log has it.
gizmo_browser_test(branch_log
  BOARD=${GIZMO_BROWSER_FIXTURES}/boards/spec-example.txt KEYS=${GIZMO_BROWSER_FIXTURES}/keys/flippers.keys
  TIME=6 PICK=3 TOLERANCE=0 BRANCH_AT=150)
# A branch of a spawner board's run, taken with spawned balls in play: each drawn from the
# branch's first keyframe on.
gizmo_browser_test(branch_log_spawned
  BOARD=${GIZMO_BROWSER_FIXTURES}/boards/gizmos/spawner.txt KEYS=${GIZMO_BROWSER_FIXTURES}/keys/flippers.keys
  TIME=4 PICK=12 TOLERANCE=0 BRANCH_AT=60)
