# The stress report must fail when a certified answer is wrong: for each kind, flip the first decided
# answer (stress_report --inject-fault, test only) and require exit status 1 and the message naming it.
foreach(kind twin hybrid exact)
  execute_process(COMMAND ${TOOL} --cases 1 --families friction_threshold --inject-fault ${kind}
                  RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT code EQUAL 1)
    message(FATAL_ERROR "--inject-fault ${kind}: exit status ${code}, expected 1\n${out}\n${err}")
  endif()
  if(NOT err MATCHES "WRONG certified answer \\(${kind}\\)")
    message(FATAL_ERROR "--inject-fault ${kind}: no report of the wrong answer\n${err}")
  endif()
endforeach()
execute_process(COMMAND ${TOOL} --cases 1 --families friction_threshold RESULT_VARIABLE code OUTPUT_QUIET ERROR_QUIET)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "without a fault the same run must pass (exit ${code})")
endif()
