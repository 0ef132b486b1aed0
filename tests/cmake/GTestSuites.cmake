# One CTest entry per GoogleTest suite ("Suite.*") rather than one per test: a test binary that links
# many shared libraries (the renderer's: 265, through OpenImageIO and LibRaw) spends 0.7 CPU s
# loading them, which one process per test paid 336 times (bench/README.md, "The fresh-clone test").
# The suites are listed after each build, as gtest_discover_tests lists tests; `ctest -R '^Suite\.'`
# still selects a suite, and the binary's --gtest_filter a single test.
set(LENSLAB_GTEST_SUITES_SCRIPT ${CMAKE_CURRENT_LIST_DIR}/GTestSuitesList.cmake)

function(lenslab_add_gtest_suites target timeout)
  set(tests_file ${CMAKE_CURRENT_BINARY_DIR}/${target}_suites.cmake)
  set(include_file ${CMAKE_CURRENT_BINARY_DIR}/${target}_suites_include.cmake)
  add_custom_command(TARGET ${target} POST_BUILD
    COMMAND ${CMAKE_COMMAND} -D TEST_EXECUTABLE=$<TARGET_FILE:${target}> -D TESTS_FILE=${tests_file}
            -D TIMEOUT=${timeout} -D WORKING_DIRECTORY=${CMAKE_CURRENT_BINARY_DIR}
            -P ${LENSLAB_GTEST_SUITES_SCRIPT}
    BYPRODUCTS ${tests_file}
    VERBATIM)
  file(WRITE ${include_file}
       "if(EXISTS \"${tests_file}\")\n  include(\"${tests_file}\")\nelse()\n"
       "  add_test(${target}_NOT_BUILT ${target}_NOT_BUILT)\nendif()\n")
  set_property(DIRECTORY APPEND PROPERTY TEST_INCLUDE_FILES ${include_file})
endfunction()
