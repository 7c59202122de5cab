# ctest's consumer test of the installed C++ package (issue 24), run as `cmake -P`:
#   1. `cmake --install BUILD --prefix TMP/prefix` (a temporary directory, not the build tree);
#   2. configure and build examples/embed_cpp against it (find_package(collidescope)), with the
#      embedding tutorial's C++ loop (docs/tutorials/embedding-loop.md, the block after
#      <!-- embed-cpp-loop -->) as a second program;
#   3. run the example on SCENE, recording; its pairs must equal `collidescope check --pairs`
#      byte for byte, and `collidescope validate` must accept its recording;
#   4. run the tutorial's loop, which must print a line per frame;
#   5. with PYTHON and PYTHON_DIR (the module is built): import the installed module from
#      PREFIX/PYTHON_DIR and step a frame, so the install's layout and RPATH are held too.
# Variables: BUILD_DIR, SOURCE_DIR, CLI (the collidescope binary), SCENE; PYTHON, PYTHON_DIR.
foreach(var BUILD_DIR SOURCE_DIR CLI SCENE)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "embed_cpp.cmake: ${var} is not set")
  endif()
endforeach()

string(RANDOM LENGTH 8 suffix)
set(tmp "/tmp/collidescope_embed_cpp_${suffix}")
file(REMOVE_RECURSE ${tmp})
file(MAKE_DIRECTORY ${tmp})

function(run_step what)
  execute_process(COMMAND ${ARGN} WORKING_DIRECTORY ${tmp} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "${what} failed (${code}):\n${out}\n${err}")
  endif()
  set(last_output "${out}" PARENT_SCOPE)
endfunction()

run_step("install" ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${tmp}/prefix)
if(NOT EXISTS ${tmp}/prefix/include/collidescope/session.hpp)
  message(FATAL_ERROR "install: no include/collidescope/session.hpp under ${tmp}/prefix")
endif()
# A small public surface (docs/reference/embedding.md): about ten headers, every one of them
# self-contained within the install, and no GL, allocator or GPU-cull pass records in them.
file(GLOB_RECURSE installed_headers RELATIVE ${tmp}/prefix/include ${tmp}/prefix/include/*.hpp)
list(LENGTH installed_headers installed_count)
if(installed_count GREATER 10)
  message(FATAL_ERROR "install: ${installed_count} headers (${installed_headers}); the package shows at most 10")
endif()
foreach(header IN LISTS installed_headers)
  file(STRINGS ${tmp}/prefix/include/${header} includes REGEX "^#include \"")
  foreach(line IN LISTS includes)
    string(REGEX REPLACE "^#include \"([^\"]+)\".*" "\\1" included "${line}")
    if(NOT EXISTS ${tmp}/prefix/include/${included})
      message(FATAL_ERROR "install: ${header} includes ${included}, which is not installed")
    endif()
  endforeach()
  file(READ ${tmp}/prefix/include/${header} text)
  foreach(word GpuPassInfo GlContext GlBackend LargeBlock)
    if(text MATCHES "${word}")
      message(FATAL_ERROR "install: ${header} names ${word}: plumbing in the public surface")
    endif()
  endforeach()
endforeach()

# The tutorial's loop, verbatim.
set(tutorial docs/tutorials/embedding-loop.md)
file(READ ${SOURCE_DIR}/${tutorial} tutorial_text)
string(REGEX MATCH "<!-- embed-cpp-loop -->\n```cpp\n([^`]*)```" block "${tutorial_text}")
if(NOT CMAKE_MATCH_1)
  message(FATAL_ERROR "${tutorial}: no ```cpp block after <!-- embed-cpp-loop -->")
endif()
file(WRITE ${tmp}/tutorial_loop.cpp "${CMAKE_MATCH_1}")

# CMAKE_PREFIX_PATH names the installed tree only; the build tree registers no package.
run_step("configure" ${CMAKE_COMMAND} -S ${SOURCE_DIR}/examples/embed_cpp -B ${tmp}/build
         -DCMAKE_PREFIX_PATH=${tmp}/prefix -DCMAKE_BUILD_TYPE=Release -DTUTORIAL_LOOP=${tmp}/tutorial_loop.cpp
         -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF)
file(STRINGS ${tmp}/build/CMakeCache.txt found REGEX "^collidescope_DIR:")
if(NOT found MATCHES "${tmp}/prefix")
  message(FATAL_ERROR "the example found collidescope elsewhere: ${found}")
endif()
run_step("build" ${CMAKE_COMMAND} --build ${tmp}/build -j2)

run_step("embed_cpp" ${tmp}/build/embed_cpp ${SCENE} ${tmp}/embed.tsv ${tmp}/embed.h5)
run_step("check" ${CLI} check --scene ${SCENE} --pairs ${tmp}/check.tsv --exit-zero -q)
file(SIZE ${tmp}/check.tsv check_size)
if(check_size EQUAL 0)
  message(FATAL_ERROR "check found no pairs on ${SCENE}: the comparison would test nothing")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${tmp}/embed.tsv ${tmp}/check.tsv RESULT_VARIABLE differ)
if(differ)
  message(FATAL_ERROR "embed_cpp's pairs differ from check --pairs on ${SCENE} (${tmp}/embed.tsv, ${tmp}/check.tsv)")
endif()
run_step("validate" ${CLI} validate ${tmp}/embed.h5)

run_step("tutorial_loop" ${tmp}/build/tutorial_loop)
if(NOT last_output MATCHES "frame 15: ")
  message(FATAL_ERROR "the tutorial's loop did not print frame 15:\n${last_output}")
endif()

set(python_note "")
if(PYTHON)
  # Newlines, not semicolons: execute_process would split its arguments at semicolons.
  string(CONCAT probe "import collidescope\n" "s = collidescope.scene('${SCENE}')\n"
         "x = collidescope.Session(s.triangles(), method='aabb')\n"
         "n = sum(len(x.step(s.positions(f))) for f in range(len(s)))\n" "print(collidescope.__file__, n)\n")
  run_step("installed python module" ${CMAKE_COMMAND} -E env PYTHONPATH=${tmp}/prefix/${PYTHON_DIR} ${PYTHON} -c "${probe}")
  file(STRINGS ${tmp}/check.tsv check_lines)
  list(LENGTH check_lines check_count)
  if(NOT last_output MATCHES "^${tmp}/prefix/${PYTHON_DIR}/collidescope/__init__.py ${check_count}\n")
    message(FATAL_ERROR "the installed module did not load from the prefix or found other pairs "
                        "(check: ${check_count}):\n${last_output}")
  endif()
  set(python_note "; the installed Python module found the same ${check_count} pairs")
endif()

file(REMOVE_RECURSE ${tmp})
message(STATUS "embed_cpp: ${check_size} bytes of pairs equal check's; the tutorial's loop ran${python_note}")
