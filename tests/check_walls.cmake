# Dependency walls (docs/design.md): run by CTest as `cmake -DROOT=<repo> -P check_walls.cmake`.
#   core/   standard library and core/ only
#   float/  no GMP, no CGAL, nothing from exact/ or proofs/
#   proofs/ no CGAL, nothing from exact/, core/, float/, cli/
#   exact/ by parts (below); testing/ no front end; conformance/ no front end, the test scenery in one file
#   exact/, conformance/, cli/: no peer library (qhull, cddlib, GLPK) and nothing from bench/
#   CGAL only in exact/cgal/ (its one opt-in header included by no other header), tests/, bench/ and one engine
#   file, exact/io/region_cgal.cpp (support regions' validity and triangulation)
#   and no project file pointing at ../shared (the self-contained documentation, below)
set(failures "")
function(check_dir dir forbidden_regex what)
  file(GLOB_RECURSE files "${ROOT}/${dir}/*.h" "${ROOT}/${dir}/*.hpp" "${ROOT}/${dir}/*.cpp")
  foreach(f IN LISTS files)
    if(DEFINED allowed_file AND f STREQUAL "${ROOT}/${allowed_file}")
      continue()
    endif()
    file(STRINGS "${f}" lines REGEX "^[ \t]*#[ \t]*include")
    foreach(line IN LISTS lines)
      if(line MATCHES "${forbidden_regex}")
        set(failures "${failures}\n  ${f}: ${line}  (${what})" PARENT_SCOPE)
      endif()
    endforeach()
  endforeach()
endfunction()
check_dir(core "<gmp|<CGAL/|<boost/|\"(exact|float|proofs|cli)/" "core/ is standard library only")
check_dir(float "<gmp|<CGAL/|\"(exact|proofs|cli)/" "float/ has no GMP, no CGAL, no exact engine")
check_dir(proofs "<CGAL/|\"(exact|core|float|cli)/" "proofs/ shares no code with the engine")
# exact/'s parts (docs/design.md, "The parts and their walls"): numbers <- io <- statics, sliding <- fixture <- certificates <- pipeline;
# nothing of the engine reaches the front ends (cli/, python/), the conformance part or the test scenery (testing/).
check_dir(exact "\"(cli|python|conformance|testing|bench|fuzz|tests)/" "the engine does not depend on front ends, conformance or test scenery")
foreach(part numbers io statics sliding fixture certificates)
  check_dir(exact/${part} "\"proofs/" "only exact/pipeline/ calls the independent checker")
endforeach()
check_dir(exact/numbers "\"exact/(io|statics|sliding|fixture|certificates|pipeline)/" "numbers/ is the bottom of exact/")
check_dir(exact/io "\"exact/(statics|sliding|fixture|certificates|pipeline)/" "io/ sits on numbers/ only")
check_dir(exact/statics "\"exact/(sliding|fixture|certificates|pipeline)/" "statics/ does not know sliding, fixtures or the pipeline")
check_dir(exact/sliding "\"exact/(statics|fixture|certificates|pipeline)/" "sliding/ does not know statics, fixtures or the pipeline")
# fixture/ (hold: contacts and the support's friction together) is the one part above both statics and sliding.
check_dir(exact/fixture "\"exact/(certificates|pipeline)/" "fixture/ sits on statics/ and sliding/, below the pipeline")
# The deciders return witnesses; certificates/ writes every certificate from them (one file per section of
# proofs/certificate-format.md), below the pipeline, which checks them.
check_dir(exact/certificates "\"exact/pipeline/" "certificates/ sits below the pipeline")
foreach(part statics sliding fixture)
  check_dir(exact/${part} "\"exact/io/json_writer\\.h\"" "deciders return witness data; JSON is written by certificates/ and the pipeline")
endforeach()
check_dir(testing "\"(cli|python|conformance)/" "test scenery does not depend on front ends or conformance")
# conformance/ (the reference corpus and compare) sits on the pipeline; only the built-in corpus
# (conformance/reference.cpp) uses the test scenery, and neither the command line nor Python includes it.
check_dir(conformance "\"(cli|python|bench|fuzz|tests)/" "conformance does not depend on front ends")
set(allowed_file conformance/reference.cpp)
foreach(dir conformance cli python)
  check_dir(${dir} "\"testing/" "the test scenery only in the built-in corpus (conformance/reference.cpp)")
endforeach()
unset(allowed_file)
# The front ends reach the twin only through the pipeline (they write the values it answered with).
foreach(front cli python)
  check_dir(${front} "\"float/|\"exact/statics/hybrid_kernel\\.h" "front ends reach the twin only through exact/pipeline/")
endforeach()
# CGAL (docs/design.md, "CGAL and Boost") is compiled in exact/cgal/ (the face and the mesh writers), tests/ and
# bench/ only: no other part of the engine, no front end, no test scenery includes it; the face's one opt-in header
# (exact/cgal/cgal.h) is included by no other header, and exact/cgal/mesh_io.h (what the command includes) has none.
# One engine file reads support regions with CGAL (exact/io/region_cgal.cpp: validity and triangulation, an object
# library linked privately).
set(allowed_file exact/io/region_cgal.cpp)
foreach(dir exact/numbers exact/io exact/statics exact/sliding exact/fixture exact/certificates exact/pipeline conformance cli python testing fuzz)
  check_dir(${dir} "<CGAL/|\"exact/cgal/cgal\\.h\"" "CGAL only in exact/cgal/, tests/, bench/ and exact/io/region_cgal.cpp")
endforeach()
unset(allowed_file)
file(GLOB_RECURSE headers "${ROOT}/exact/*.h" "${ROOT}/core/*.h" "${ROOT}/float/*.h" "${ROOT}/proofs/*.h")
foreach(h IN LISTS headers)
  if(h MATCHES "/exact/cgal/cgal\\.h$")
    continue()
  endif()
  file(STRINGS "${h}" lines REGEX "^[ \t]*#[ \t]*include.*(<CGAL/|exact/cgal/cgal\\.h)")
  foreach(line IN LISTS lines)
    set(failures "${failures}\n  ${h}: ${line}  (CGAL's headers reach a user only through exact/cgal/cgal.h)")
  endforeach()
endforeach()

# The benchmarks' peers (qhull, cddlib, GLPK, bench/) are never part of the engine or the command.
foreach(dir exact conformance cli)
  check_dir(${dir} "<libqhull|<cdd/|<glpk|\"bench/" "peers stay in bench/")
endforeach()

# Self-contained documentation (docs/theory.md): no project file points at the team's workspace outside
# the repository ("../shared", "shared/docs", or the team's spec pages by name: interface.md, peers.md,
# toolchain.md, house-style.md), which users do not have. Checks the tracked files (every
# file when ROOT is not a git checkout) under the listed paths, comments and printed strings alike.
set(doc_paths README.md docs cli conformance exact float core proofs python bench fuzz tests testing)
set(doc_files "")
find_program(GIT_EXECUTABLE git)
if(GIT_EXECUTABLE AND EXISTS "${ROOT}/.git")
  execute_process(COMMAND "${GIT_EXECUTABLE}" -C "${ROOT}" -c core.quotePath=false ls-files -- ${doc_paths}
                  OUTPUT_VARIABLE listed RESULT_VARIABLE git_rc OUTPUT_STRIP_TRAILING_WHITESPACE)
  if(git_rc EQUAL 0)
    string(REPLACE "\n" ";" doc_files "${listed}")
    list(TRANSFORM doc_files PREPEND "${ROOT}/")
  endif()
endif()
if(NOT doc_files)
  foreach(p IN LISTS doc_paths)
    if(IS_DIRECTORY "${ROOT}/${p}")
      file(GLOB_RECURSE found "${ROOT}/${p}/*")
      list(APPEND doc_files ${found})
    elseif(EXISTS "${ROOT}/${p}")
      list(APPEND doc_files "${ROOT}/${p}")
    endif()
  endforeach()
endif()
list(FILTER doc_files EXCLUDE REGEX "/tests/check_walls\\.cmake$")
list(LENGTH doc_files doc_count)
if(doc_count LESS 100)
  set(failures "${failures}\n  only ${doc_count} files found under ${doc_paths}: the documentation check did not run")
endif()
foreach(f IN LISTS doc_files)
  if(NOT EXISTS "${f}" OR IS_DIRECTORY "${f}")
    continue()
  endif()
  file(STRINGS "${f}" hits REGEX "\\.\\./shared|shared/docs|interface\\.md|peers\\.md|toolchain\\.md|house-style\\.md")
  foreach(line IN LISTS hits)
    set(failures "${failures}\n  ${f}: ${line}  (points outside the repository; cite docs/ instead)")
  endforeach()
endforeach()

if(failures)
  message(FATAL_ERROR "dependency walls broken:${failures}")
endif()
message(STATUS "dependency walls hold")
