#pragma once
// The player's page, style and script (cli/render/), compiled in so that `gizmo render` works
// from any directory and after installation.
namespace gizmo::cli {
extern const char* const kPlayerHtml;
extern const char* const kPlayerCss;
extern const char* const kPlayerJs;
}  // namespace gizmo::cli
