# Sourced by scripts/build and scripts/fuzz: the CMake arguments that compile through ccache
# (scripts/setup installs it), so a second clone of the same sources, or a rebuild after
# `git clean`, compiles only what changed. Keys are taken relative to the clone
# (CCACHE_BASEDIR), so clones at different paths share one cache (ccache's default,
# ~/.cache/ccache). The precompiled test headers need the pch_defines and time_macros
# sloppiness. Nothing is added when ccache is missing or the caller chose a launcher.
compiler_cache_args() {
  local root="$1"
  if ! command -v ccache >/dev/null 2>&1 || [ -n "${CMAKE_CXX_COMPILER_LAUNCHER:-}" ]; then return; fi
  local launcher="env;CCACHE_BASEDIR=$root;CCACHE_SLOPPINESS=pch_defines,time_macros;ccache"
  printf '%s\n' "-DCMAKE_C_COMPILER_LAUNCHER=$launcher" "-DCMAKE_CXX_COMPILER_LAUNCHER=$launcher"
}
