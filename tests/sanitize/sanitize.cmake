# Included by the top-level CMakeLists.txt after every target exists, when COLLIDESCOPE_SANITIZE
# is set (docs/how-to/sanitizers.md). Gives every executable (the app, the tests, the benchmarks) the
# sanitizer's built-in options and suppressions, so `ctest` and the app need no environment,
# and in the thread build links the TBB bridge first (tbb_tsan_bridge.cpp).

if(COLLIDESCOPE_SANITIZE STREQUAL "thread")
  # The bridge: an ITT collector that turns TBB's notifications into TSan happens-before edges,
  # and interposers for TBB's allocators. A shared library: it must be a DT_NEEDED
  # entry before libtbb so that its allocator definitions come first in the lookup order.
  add_library(collidescope_tbb_tsan_bridge SHARED ${CMAKE_CURRENT_LIST_DIR}/tbb_tsan_bridge.cpp)
  target_link_libraries(collidescope_tbb_tsan_bridge PRIVATE ${CMAKE_DL_LIBS})
  set(sanitizer_defaults ${CMAKE_CURRENT_LIST_DIR}/thread_defaults.cpp)

  # The bridge's own check: TBB loops are quiet, a race planted in a loop body is reported.
  if(COLLIDESCOPE_TESTS)
    add_executable(tbb_race_canary ${CMAKE_CURRENT_LIST_DIR}/tbb_race_canary.cpp)
    target_link_libraries(tbb_race_canary PRIVATE TBB::tbb)
    add_test(NAME sanitize.tbb_clean_loops_are_quiet COMMAND tbb_race_canary clean)
    add_test(NAME sanitize.tbb_planted_race_is_reported COMMAND tbb_race_canary race)
    set_tests_properties(sanitize.tbb_planted_race_is_reported PROPERTIES
      PASS_REGULAR_EXPRESSION "SUMMARY: ThreadSanitizer: data race [^\n]*tbb_race_canary.cpp:[0-9]+ in")
    set_tests_properties(sanitize.tbb_clean_loops_are_quiet sanitize.tbb_planted_race_is_reported
      PROPERTIES LABELS sanitize)
  endif()
else()
  set(sanitizer_defaults ${CMAKE_CURRENT_LIST_DIR}/address_defaults.cpp)
endif()

# The defaults are compiled once, as an object library whose object every executable links.
add_library(collidescope_sanitizer_defaults OBJECT ${sanitizer_defaults})

function(collidescope_sanitize_executables directory)
  get_property(targets DIRECTORY ${directory} PROPERTY BUILDSYSTEM_TARGETS)
  get_property(subdirectories DIRECTORY ${directory} PROPERTY SUBDIRECTORIES)
  foreach(subdirectory IN LISTS subdirectories)
    collidescope_sanitize_executables(${subdirectory})
  endforeach()
  foreach(target IN LISTS targets)
    get_target_property(type ${target} TYPE)
    if(NOT type STREQUAL "EXECUTABLE")
      continue()
    endif()
    target_link_libraries(${target} PRIVATE collidescope_sanitizer_defaults)
    if(TARGET collidescope_tbb_tsan_bridge)
      # First on the link line (and so first among the DT_NEEDED libraries after libtsan).
      get_target_property(libraries ${target} LINK_LIBRARIES)
      if(NOT libraries)
        set(libraries "")
      endif()
      set_target_properties(${target} PROPERTIES LINK_LIBRARIES "collidescope_tbb_tsan_bridge;${libraries}")
    endif()
  endforeach()
endfunction()

collidescope_sanitize_executables(${CMAKE_SOURCE_DIR})

# Optimisation: scripts/sanitize.sh compiles the address build at -Og (UBSan's checks made a
# test file's compile 2.2 times slower at -O2 than at -O1: 40 against 18 s for
# tests/app/test_check_outputs.cpp; the whole build took about 26 of CI's 90 minutes at -O2;
# -Og compiles in about half the time of -O1 again, docs/how-to/sanitizers.md),
# and the code the suite spends its time in at -O1 (scripts/sanitize.sh): the engine's loops,
# and the support library's references (brute force, exact rational tests) that the tests
# compare them with.
if(COLLIDESCOPE_SANITIZE STREQUAL "address" AND COLLIDESCOPE_SANITIZE_HOT_OPTIMIZATION)
  foreach(target collidescope_engine collidescope_test_support)
    if(TARGET ${target})
      target_compile_options(${target} PRIVATE ${COLLIDESCOPE_SANITIZE_HOT_OPTIMIZATION})
    endif()
  endforeach()
endif()
