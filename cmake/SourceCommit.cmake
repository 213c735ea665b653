# Run at build time (cmake -P): writes OUT, a header defining ONDINE_SOURCE_COMMIT, the commit the
# binary is built from (git rev-parse --short HEAD), "+modified" when the solver's tracked sources
# (src, kernels, cases, CMakeLists.txt) differ from it, "unknown" without git. The file is
# rewritten only when that changes, so a commit recompiles only what includes it.
execute_process(COMMAND git -C "${SRC}" rev-parse --short HEAD OUTPUT_VARIABLE head OUTPUT_STRIP_TRAILING_WHITESPACE
                RESULT_VARIABLE rc ERROR_QUIET)
if(NOT rc EQUAL 0 OR head STREQUAL "")
  set(commit "unknown")
else()
  execute_process(COMMAND git -C "${SRC}" status --porcelain --untracked-files=no -- src kernels cases CMakeLists.txt
                  OUTPUT_VARIABLE changes OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
  set(commit "${head}")
  if(NOT changes STREQUAL "")
    set(commit "${head}+modified")
  endif()
endif()
set(text "#pragma once\n#define ONDINE_SOURCE_COMMIT \"${commit}\"\n")
if(EXISTS "${OUT}")
  file(READ "${OUT}" old)
endif()
if(NOT "${old}" STREQUAL "${text}")
  file(WRITE "${OUT}" "${text}")
endif()
