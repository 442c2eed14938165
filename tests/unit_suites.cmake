# Writes the unit tests' CTest file (cmake -P, after unit_tests links): one
# CTest test per GoogleTest suite, "Suite.*", and a test of its own for each
# test named in ALONE (left out of its suite's run). A process pays the
# start-up of the libraries deal.II brings (about 0.3 to 0.6 s) once per
# suite, not once per test.
#   EXECUTABLE   the unit_tests program
#   OUTPUT       the file to write
#   DIRECTORY    the tests' working directory
#   ALONE        test names, separated by '|'
#   COSTS        NAME:SECONDS pairs, separated by '|': CTest starts the
#                longest first (a fresh build has no timings of its own)
#   SKIPPED      the exit code of a run that skipped every test
cmake_minimum_required(VERSION 3.13)
execute_process(COMMAND "${EXECUTABLE}" --gtest_list_tests
                OUTPUT_VARIABLE listing RESULT_VARIABLE status TIMEOUT 60)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "${EXECUTABLE} --gtest_list_tests failed (${status}):\n${listing}")
endif()
string(REPLACE "|" ";" alone "${ALONE}")
string(REPLACE "|" ";" costs "${COSTS}")

set(suites "")
string(REPLACE "\n" ";" lines "${listing}")
foreach(line IN LISTS lines)
  if(line MATCHES "^([A-Za-z0-9_]+)\\.$")
    set(suite "${CMAKE_MATCH_1}")
    list(APPEND suites "${suite}")
    set(left_out_${suite} "")
  elseif(line MATCHES "^  ([A-Za-z0-9_]+)")
    set(test "${suite}.${CMAKE_MATCH_1}")
    if(test IN_LIST alone)
      list(APPEND left_out_${suite} "${test}")
    endif()
  elseif(NOT line STREQUAL "")
    # A parameterised or typed test ("Instance/Suite.") would be run by no
    # CTest test: the names above are all this file knows.
    message(FATAL_ERROR "${EXECUTABLE} --gtest_list_tests: a line read as no suite and no test: '${line}'")
  endif()
endforeach()
foreach(test IN LISTS alone)
  string(REGEX REPLACE "\\..*" "" suite "${test}")
  if(NOT "${test}" IN_LIST left_out_${suite})
    message(FATAL_ERROR "ALONE names ${test}, which ${EXECUTABLE} does not list")
  endif()
endforeach()
list(LENGTH suites count)
if(count EQUAL 0)
  message(FATAL_ERROR "${EXECUTABLE} lists no test suite:\n${listing}")
endif()

# A run whose every test was skipped (GTEST_SKIP) exits SKIPPED
# (tests/unit/main.cc): CTest shows it skipped. A failure exits 1, whatever
# else was skipped.
set(text "")
macro(add_unit_test name filter)
  string(APPEND text "add_test([==[${name}]==] [==[${EXECUTABLE}]==] [==[--gtest_filter=${filter}]==])\n"
                     "set_tests_properties([==[${name}]==] PROPERTIES WORKING_DIRECTORY [==[${DIRECTORY}]==]"
                     " SKIP_RETURN_CODE ${SKIPPED})\n")
endmacro()
foreach(suite IN LISTS suites)
  set(filter "${suite}.*")
  if(left_out_${suite})
    list(JOIN left_out_${suite} ":" left)
    string(APPEND filter "-${left}")
    foreach(test IN LISTS left_out_${suite})
      add_unit_test("${test}" "${test}")
    endforeach()
  endif()
  add_unit_test("${suite}.*" "${filter}")
endforeach()
foreach(pair IN LISTS costs)
  string(REGEX MATCH "^(.*):([0-9]+)$" matched "${pair}")
  string(APPEND text "set_tests_properties([==[${CMAKE_MATCH_1}]==] PROPERTIES COST ${CMAKE_MATCH_2})\n")
endforeach()
file(WRITE "${OUTPUT}" "${text}")
