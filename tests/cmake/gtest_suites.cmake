# Writes a CTest include file with one test per GoogleTest suite of a test executable (run after each
# build of the executable; see ochre_test_executable in tests/CMakeLists.txt).
#
#   cmake -DEXE=<test executable> -DOUT=<file to write> -DPREFIX=<test name prefix> -DLABEL=<label>
#         -DWORKDIR=<working directory> -P gtest_suites.cmake
#
# Each test is named PREFIX/SUITE and runs `EXE --gtest_filter=SUITE.*`. A process that reads or writes an
# image loads OpenImageIO and its ~260 shared libraries (0.2-0.5 s), more than most tests take: one process
# per suite instead of one per test saves about a minute of the suite on 2 cores.
# A run whose every test skipped prints the marker of tests/support/test_main.cpp and is reported skipped;
# a run with failures never prints it.
foreach(arg EXE OUT PREFIX LABEL WORKDIR)
  if(NOT DEFINED ${arg})
    message(FATAL_ERROR "gtest_suites.cmake: -D${arg}=... is required")
  endif()
endforeach()

execute_process(COMMAND "${EXE}" --gtest_list_tests WORKING_DIRECTORY "${WORKDIR}" OUTPUT_VARIABLE listing
                RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "gtest_suites.cmake: ${EXE} --gtest_list_tests failed (${status}):\n${listing}")
endif()

# Suite lines are flush left and end with '.', optionally followed by "  # TypeParam = ..."; test lines are
# indented.
string(REPLACE ";" "\\;" listing "${listing}")
string(REPLACE "\n" ";" lines "${listing}")
set(content "")
set(count 0)
foreach(line IN LISTS lines)
  if(line MATCHES "^([A-Za-z_][A-Za-z0-9_/]*)\\.(  #.*)?$")
    set(suite "${CMAKE_MATCH_1}")
    set(name "${PREFIX}/${suite}")
    string(APPEND content
           "add_test([==[${name}]==] [==[${EXE}]==] [==[--gtest_filter=${suite}.*]==])\n"
           "set_tests_properties([==[${name}]==] PROPERTIES WORKING_DIRECTORY [==[${WORKDIR}]==] "
           "LABELS [==[${LABEL}]==] SKIP_REGULAR_EXPRESSION [==[ochre-tests: every selected test was skipped]==])\n")
    math(EXPR count "${count} + 1")
  endif()
endforeach()
if(count EQUAL 0)
  message(FATAL_ERROR "gtest_suites.cmake: no test suite in the listing of ${EXE}:\n${listing}")
endif()
file(WRITE "${OUT}" "${content}")
