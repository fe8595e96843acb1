#pragma once
// Internal to gizmo::io: the commands that other Gizmoball programs added to the text format and
// that the core does not simulate. This table is the one place the text reader learns of them:
// each is left out of the board with a warning that names it (and so are the later commands that
// name what it created). When the core gains one of these gizmos, its entry moves from here to the
// reader's own command table.
#include <cstddef>
#include <string_view>

namespace gizmo::io::detail {

enum class AdditionKind {
  Gizmo,       // creates an object named by token 1; later commands naming it are dropped
  Decoration,  // changes how a named object looks (a colour): ignored, the object stays
  Input,       // binds an input other than a key (a mouse button): dropped
};

struct Addition {
  std::string_view word;  // as its program spells it (matched without regard to case)
  AdditionKind kind;
  std::string_view what;     // plain words for the warning: "a ball sink"
  std::string_view program;  // where it comes from (docs/board-files.md gives file and line)
};

// The addition spelled `word` (any case), or null.
const Addition* findAddition(std::string_view word);

// d-g-n/CS308-GizmoBall's spinner, spelled as NiklavsM/Gizmoball's (`Spinner NAME X Y`), which the
// core simulates: told apart by its name (whether a line is d-g-n's is the dialects table's to
// decide, text_dialects.cpp).
const Addition& dgnSpinner();

}  // namespace gizmo::io::detail
