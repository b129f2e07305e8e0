# CTest driver of the consumer project: cmake -DBUILD=<wrenchkit build> -DSOURCE=<this dir>
# -DWORK=<scratch dir> -DGENERATOR=<generator> [-DPYTHON=<python3>] -P run.cmake
# 1. cmake --install BUILD --prefix WORK/prefix
# 2. configure, build and run tests/consumer against the prefix (wrenchkit::exact, ::checker, ::float, and
#    ::cgal: a golden scene's labels and the barbell's limit surface as CGAL objects, checked by CGAL)
# 3. again with only COMPONENTS float while GMP cannot be found (the float twin needs no GMP)
# 4. the installed CLI answers, theory.md (which its help cites) is installed, and the installed Python
#    package imports (when built)
function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    string(REPLACE ";" " " cmd "${ARGN}")
    message(FATAL_ERROR "failed (${rc}): ${cmd}\n${out}\n${err}")
  endif()
  message(STATUS "${out}")
endfunction()

file(REMOVE_RECURSE "${WORK}")
set(prefix "${WORK}/prefix")
run(${CMAKE_COMMAND} --install "${BUILD}" --prefix "${prefix}")

run(${CMAKE_COMMAND} -S "${SOURCE}" -B "${WORK}/all" -G "${GENERATOR}" -DCMAKE_PREFIX_PATH=${prefix}
    -DCMAKE_BUILD_TYPE=Release)
run(${CMAKE_COMMAND} --build "${WORK}/all")
run("${WORK}/all/consumer_exact")
run("${WORK}/all/consumer_cgal" "${SOURCE}/../golden/two_finger_y9_10_mu1_4.scene.json")
run("${WORK}/all/consumer_float")

# GMP made unfindable: the system's include and library directories are ignored by find_* (an initial
# cache file, because a list cannot pass through run()'s arguments).
set(no_gmp "${WORK}/no_gmp.cmake")
file(WRITE "${no_gmp}"
  "set(CMAKE_IGNORE_PATH /usr/include /usr/lib /usr/lib/x86_64-linux-gnu /usr/local/include /usr/local/lib CACHE STRING \"\")\n")
run(${CMAKE_COMMAND} -S "${SOURCE}" -B "${WORK}/float" -G "${GENERATOR}" -DCMAKE_PREFIX_PATH=${prefix}
    -DCMAKE_BUILD_TYPE=Release -DWRENCHKIT_CONSUMER_FLOAT_ONLY=ON -C "${no_gmp}")
run(${CMAKE_COMMAND} --build "${WORK}/float")
run("${WORK}/float/consumer_float")
# ... and then the full package must refuse with a clear message.
execute_process(COMMAND ${CMAKE_COMMAND} -S "${SOURCE}" -B "${WORK}/nogmp" -G "${GENERATOR}"
    -DCMAKE_PREFIX_PATH=${prefix} -C "${no_gmp}"
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(rc EQUAL 0 OR NOT err MATCHES "need GMP")
  message(FATAL_ERROR "find_package(wrenchkit) without GMP should fail naming GMP:\n${out}\n${err}")
endif()

run("${prefix}/bin/wrenchkit" --version)
# The document the CLI's help cites ("theory.md §1.5") is installed beside it.
file(GLOB_RECURSE theory "${prefix}/share/doc/*/theory.md")
if(NOT theory)
  message(FATAL_ERROR "docs/theory.md is not installed under ${prefix}/share/doc")
endif()
run("${prefix}/bin/wrenchkit" demo)
if(PYTHON)
  file(GLOB_RECURSE init "${prefix}/*.py")
  list(FILTER init INCLUDE REGEX "/wrenchkit/__init__\\.py$")
endif()
if(PYTHON AND init)  # the package is installed when the bindings were built (python/)
  list(GET init 0 init)
  get_filename_component(site "${init}" DIRECTORY)
  get_filename_component(site "${site}" DIRECTORY)
  file(WRITE "${WORK}/use_wrenchkit.py" [=[
import wrenchkit
s = wrenchkit.Scene({"contacts": [{"at": [0, "1/2"], "normal": [1, 0], "mu": 0.1},
                                  {"at": [1, "1/2"], "normal": [-1, 0], "mu": 0.1}]})
r = wrenchkit.closure(s)
assert r["force_closure"] and not r["form_closure"]
assert wrenchkit.check(s, r["certificate"])["accepted"]
print("python: the installed package answers", wrenchkit.__file__)
]=])
  run(${CMAKE_COMMAND} -E env "PYTHONPATH=${site}" "${PYTHON}" "${WORK}/use_wrenchkit.py")
endif()
