#pragma once
// The pages' files (cli/render/), compiled in so that `gizmo render` and `gizmo play` work from
// any directory and after installation.
namespace gizmo::cli {
extern const char* const kPlayerHtml;
extern const char* const kPlayerCss;
extern const char* const kPlayerJs;
extern const char* const kRunDataJs;  // the run's decoding and its state at a moment (both pages')
extern const char* const kPlayHtml;
extern const char* const kPlayCss;
extern const char* const kPlayJs;
extern const char* const kBoardViewJs;     // the board drawing both pages share
extern const char* const kTimelineViewJs;  // the whole run's timeline both pages share
}  // namespace gizmo::cli
