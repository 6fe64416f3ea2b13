# ctest's Regression.HtmlReport (tests/CMakeLists.txt): runs the regression suite of tests/regression with
# its HTML report into REPORT (build/regression-report, the folder CI keeps; docs/tools.md). The report
# left there by the previous run, when there is one, gives the history.
#   cmake -DREGRESS=ochre-regress -DSUITE=tests/regression -DREPORT=... -DOUTPUT_DIR=... -P regression_report.cmake
set(_args ${SUITE} --html ${REPORT} --output-dir ${OUTPUT_DIR})
if(EXISTS ${REPORT}/.ochre-regress-report)
  list(APPEND _args --history ${REPORT})
endif()
execute_process(COMMAND ${REGRESS} ${_args} RESULT_VARIABLE _result)
if(EXISTS ${REPORT}/index.html)
  message("Regression report: file://${REPORT}/index.html")
endif()
if(NOT _result EQUAL 0)
  message(FATAL_ERROR "ochre-regress ${SUITE} exited with ${_result}")
endif()
