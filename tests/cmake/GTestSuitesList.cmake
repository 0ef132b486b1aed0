# Script mode (cmake -P): lists TEST_EXECUTABLE's suites and writes TESTS_FILE, one add_test per
# suite with the given TIMEOUT and WORKING_DIRECTORY. Called by lenslab_add_gtest_suites after a build.
execute_process(COMMAND ${TEST_EXECUTABLE} --gtest_list_tests
                OUTPUT_VARIABLE listing RESULT_VARIABLE status TIMEOUT 60)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "${TEST_EXECUTABLE} --gtest_list_tests failed (${status}):\n${listing}")
endif()
# Suite lines start in column 0 and end with "." (a typed suite adds "  # TypeParam = ...").
string(REGEX MATCHALL "(^|\n)[^ \n][^ \n]*\\." suites "${listing}")
set(text "")
foreach(suite IN LISTS suites)
  string(STRIP "${suite}" suite)
  string(APPEND text "add_test([==[${suite}*]==] \"${TEST_EXECUTABLE}\" [==[--gtest_filter=${suite}*]==])\n"
         "set_tests_properties([==[${suite}*]==] PROPERTIES TIMEOUT ${TIMEOUT} WORKING_DIRECTORY \"${WORKING_DIRECTORY}\")\n")
endforeach()
file(WRITE ${TESTS_FILE} "${text}")
