# CTest driver of the worked example docs/compare-example.md: the qhull method of docs/examples/
# qhull_closure.py (scipy, Debian python3-scipy) over the reference corpus, compared by wrenchkit compare.
#   cmake -DCLI=<wrenchkit> -DPYTHON=<python3> -DSCRIPT=<qhull_closure.py> -DWORK=<dir> -P qhull_example.cmake
# Skipped (the test's SKIP_REGULAR_EXPRESSION) when scipy cannot be imported. Checks the example's claims, not qhull's exact counts:
# compare exits 1; the disagreements include near-boundary family scenes; with --errors-as-false the
# scale-1e-20 golden grasp (far from any boundary: the method's own scale bug) is listed first.
execute_process(COMMAND "${PYTHON}" -c "import scipy.spatial" RESULT_VARIABLE rc OUTPUT_QUIET ERROR_QUIET)
if(NOT rc EQUAL 0)
  message(STATUS "SKIPPED: python3-scipy is not installed")
  return()
endif()
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
set(corpus "${WORK}/corpus")
execute_process(COMMAND "${CLI}" reference --out "${corpus}" RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "wrenchkit reference failed (${rc})")
endif()

function(qhull_run tag)
  execute_process(COMMAND "${PYTHON}" "${SCRIPT}" "${corpus}" ${ARGN} OUTPUT_FILE "${WORK}/${tag}.jsonl"
    RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "qhull_closure.py ${ARGN} failed (${rc}):\n${err}")
  endif()
  execute_process(COMMAND "${CLI}" compare "${corpus}" "${WORK}/${tag}.jsonl" RESULT_VARIABLE rc
    OUTPUT_VARIABLE out ERROR_VARIABLE err)
  message(STATUS "qhull ${tag}:\n${out}")
  if(NOT rc EQUAL 1)
    message(FATAL_ERROR "compare should find disagreements (exit 1), got ${rc}:\n${err}")
  endif()
  set(out "${out}" PARENT_SCOPE)
endfunction()

qhull_run(default)
if(NOT out MATCHES "answers with an error" OR NOT out MATCHES "near a degenerate boundary:\n  [a-z_]+\\.1e-")
  message(FATAL_ERROR "expected qhull errors and near-boundary family disagreements")
endif()
qhull_run(errors_as_false --errors-as-false)
string(FIND "${out}" "far from any degenerate boundary:" far)
string(FIND "${out}" "golden.two_finger_scale_1e-20" scale)
string(FIND "${out}" "near a degenerate boundary:" near)
if(far LESS 0 OR scale LESS far OR (near GREATER_EQUAL 0 AND scale GREATER near))
  message(FATAL_ERROR "expected golden.two_finger_scale_1e-20 among the disagreements far from any boundary")
endif()
