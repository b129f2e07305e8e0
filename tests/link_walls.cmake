# The link walls of docs/design.md ("The parts and their walls"): one library per part, each linking only what
# its walls allow. Proved twice, from the build itself rather than from the includes (tests/check_walls.cmake):
# 1. by the linker: each library below is linked on its own as a shared library of its objects with
#    --no-undefined against only what its target links, so code that calls across a wall fails the build;
# 2. by CTest (`link_walls`): each target's link libraries, as CMake holds them, against the allowed ones below.
# Included from the top-level CMakeLists.txt after every target exists (tests on, not the fuzz build); the check
# runs as cmake -DLINKS=<build>/link_walls/links.cmake -P tests/link_walls.cmake.
set(wrenchkit_walled_libraries
  wrenchkit_float wrenchkit_checker
  wrenchkit_numbers wrenchkit_io wrenchkit_statics wrenchkit_sliding wrenchkit_fixture wrenchkit_certificates
  wrenchkit_pipeline
  wrenchkit_cgal wrenchkit_mesh_io wrenchkit_conformance)
# Checked by CTest only (their objects are not position-independent, or need Boost.Program_options, which the
# command and the Python module link each their own way): what may reach the test scenery.
set(wrenchkit_walled_targets wrenchkit_builtin_corpus wrenchkit_testing wrenchkit_cli)
if(TARGET wrenchkit_python)
  list(APPEND wrenchkit_walled_targets wrenchkit_python)
endif()

if(CMAKE_SCRIPT_MODE_FILE)
  cmake_minimum_required(VERSION 3.20)
  include("${LINKS}")  # links_<target>: the target's link libraries (an INTERFACE target's interface ones)
  set(gmp wrenchkit_gmp)
  set(allowed_wrenchkit_float wrenchkit_core)
  set(allowed_wrenchkit_checker ${gmp})
  set(allowed_wrenchkit_numbers wrenchkit_core wrenchkit_float ${gmp})
  set(allowed_wrenchkit_io wrenchkit_numbers ${allowed_wrenchkit_numbers})
  set(allowed_wrenchkit_statics wrenchkit_io ${allowed_wrenchkit_io})  # not sliding, fixture or the pipeline
  set(allowed_wrenchkit_sliding wrenchkit_io ${allowed_wrenchkit_io})  # not statics, fixture or the pipeline
  set(allowed_wrenchkit_fixture wrenchkit_statics wrenchkit_sliding ${allowed_wrenchkit_io})
  set(allowed_wrenchkit_certificates wrenchkit_fixture ${allowed_wrenchkit_fixture})  # writes; decides nothing
  set(allowed_wrenchkit_exact wrenchkit_numbers wrenchkit_io wrenchkit_statics wrenchkit_sliding wrenchkit_fixture
      wrenchkit_certificates)
  set(allowed_wrenchkit_pipeline wrenchkit_certificates ${allowed_wrenchkit_certificates} wrenchkit_checker
      Threads::Threads)
  set(allowed_wrenchkit_cgal wrenchkit_statics wrenchkit_sliding ${allowed_wrenchkit_io} CGAL::CGAL)
  set(allowed_wrenchkit_mesh_io wrenchkit_sliding ${allowed_wrenchkit_io} CGAL::CGAL)
  # conformance/: the corpus' format and compare on the pipeline; the built-in corpus also on the test scenery.
  set(allowed_wrenchkit_conformance wrenchkit_pipeline ${allowed_wrenchkit_pipeline})
  set(allowed_wrenchkit_builtin_corpus wrenchkit_conformance wrenchkit_testing)
  set(allowed_wrenchkit_testing wrenchkit_pipeline)  # (the constructions' JSON parts, for its messages)
  # The command line's library, shared with the Python bindings: the pipeline and the mesh writers, no conformance.
  set(allowed_wrenchkit_cli wrenchkit_pipeline wrenchkit_mesh_io Boost::headers)
  set(failures "")
  foreach(t IN LISTS wrenchkit_walled_libraries wrenchkit_walled_targets ITEMS wrenchkit_exact)
    if(NOT DEFINED links_${t})
      string(APPEND failures "\n  ${t}: not in ${LINKS}")
    endif()
    if(NOT DEFINED allowed_${t})
      continue()
    endif()
    foreach(l IN LISTS links_${t})
      if(NOT l IN_LIST allowed_${t})
        string(APPEND failures "\n  ${t} links ${l} (allowed: ${allowed_${t}})")
      endif()
    endforeach()
  endforeach()
  # What a target reaches through the others: the test scenery only from the built-in corpus (and tests/, fuzz/,
  # bench/); the command line's library and the Python bindings never reach the test scenery or the built-in corpus.
  set(unreachable_wrenchkit_cli wrenchkit_testing wrenchkit_builtin_corpus wrenchkit_conformance)
  set(unreachable_wrenchkit_python wrenchkit_testing wrenchkit_builtin_corpus)
  set(unreachable_wrenchkit_conformance wrenchkit_testing wrenchkit_builtin_corpus)
  foreach(t wrenchkit_cli wrenchkit_python wrenchkit_conformance)
    if(NOT DEFINED links_${t})
      continue()
    endif()
    set(reached "")
    set(next ${links_${t}})
    while(next)
      list(POP_FRONT next l)
      if(NOT l IN_LIST reached)
        list(APPEND reached ${l})
        list(APPEND next ${links_${l}})
      endif()
    endwhile()
    foreach(u IN LISTS unreachable_${t})
      if(u IN_LIST reached)
        string(APPEND failures "\n  ${t} reaches ${u} (it links: ${reached})")
      endif()
    endforeach()
  endforeach()
  if(failures)
    message(FATAL_ERROR "link walls broken:${failures}")
  endif()
  message(STATUS "link walls hold")
  return()
endif()

set(dir "${PROJECT_BINARY_DIR}/link_walls")
set(links "")
foreach(t IN LISTS wrenchkit_walled_libraries)
  add_library(${t}_link_wall SHARED $<TARGET_OBJECTS:${t}>)
  target_link_libraries(${t}_link_wall PRIVATE ${t})
  target_link_options(${t}_link_wall PRIVATE LINKER:--no-undefined)
  set_target_properties(${t}_link_wall PROPERTIES LIBRARY_OUTPUT_DIRECTORY "${dir}")
  get_target_property(l ${t} LINK_LIBRARIES)
  string(APPEND links "set(links_${t} \"${l}\")\n")
endforeach()
foreach(t IN LISTS wrenchkit_walled_targets)
  get_target_property(l ${t} LINK_LIBRARIES)
  string(APPEND links "set(links_${t} \"${l}\")\n")
endforeach()
get_target_property(l wrenchkit_exact INTERFACE_LINK_LIBRARIES)
string(APPEND links "set(links_wrenchkit_exact \"${l}\")\n")
file(WRITE "${dir}/links.cmake" "${links}")
add_test(NAME link_walls COMMAND ${CMAKE_COMMAND} -DLINKS=${dir}/links.cmake -P ${CMAKE_CURRENT_LIST_FILE})
