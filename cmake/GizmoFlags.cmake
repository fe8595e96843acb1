# Flags every gizmo target gets, through the interface target gizmo_flags.
# Determinism: no FMA contraction (gcc's default in GNU mode is -ffp-contract=fast), no fast-math
# and no CPU-specific code generation: the simulator's doubles must be the same bits on every x86-64.
add_library(gizmo_flags INTERFACE)
target_compile_options(gizmo_flags INTERFACE -Wall -Wextra -ffp-contract=off)
# g++ 12 warns -Wrestrict inside libstdc++ for `"text" + std::string` at -O2 (GCC PR 105651, a
# false positive fixed in g++ 13); nothing in our code can address it.
if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_CXX_COMPILER_VERSION VERSION_LESS 13)
  target_compile_options(gizmo_flags INTERFACE -Wno-restrict)
endif()
# gizmo_flags is build policy, not a usage requirement: targets link it as
# $<BUILD_INTERFACE:gizmo_flags>, so it is never exported. What a consumer of the installed
# libraries does need is declared on gizmo_core itself: -ffp-contract=off, and in a sanitized
# build the sanitizer runtimes at link time (GIZMO_SANITIZER_LINK_OPTIONS).
set(GIZMO_SANITIZER_LINK_OPTIONS "")
if(GIZMO_SANITIZE)
  # g++ 12 under the sanitizers (at -O1) sees std::optional<float128>'s storage as "maybe used
  # uninitialized" inside Boost's float128 copy, in every file that returns one; the optional is
  # engaged before it is read. The release build keeps the warning on and is clean.
  target_compile_options(gizmo_flags INTERFACE -Wno-maybe-uninitialized)
  set(GIZMO_SANITIZER_LINK_OPTIONS -fsanitize=address,undefined)
  target_compile_options(gizmo_flags INTERFACE -fsanitize=address,undefined -fno-omit-frame-pointer
                                               -fno-sanitize-recover=undefined)
  target_link_options(gizmo_flags INTERFACE ${GIZMO_SANITIZER_LINK_OPTIONS})
endif()
