# prisca_add_test(<name> SOURCES <files...> LIBRARIES <targets...> LABELS <labels...>
#                  [TIMEOUT <seconds>] [FUNCTIONS <test functions...>])
# One QtTest executable registered with CTest; tests always run offscreen. With FUNCTIONS, each
# of the executable's test functions is its own CTest test (<name>.<function>), so that the
# minutes-long ones run side by side under `ctest -j`.
function(prisca_add_test name)
    cmake_parse_arguments(ARG "" "TIMEOUT" "SOURCES;LIBRARIES;LABELS;FUNCTIONS" ${ARGN})
    add_executable(${name} ${ARG_SOURCES})
    target_link_libraries(${name} PRIVATE Qt6::Test ${ARG_LIBRARIES})
    # Test helpers shared by several suites ("support/...").
    target_include_directories(${name} PRIVATE ${PROJECT_SOURCE_DIR}/tests)
    target_compile_definitions(${name} PRIVATE
        PRISCA_TEST_DATA_DIR="${PROJECT_SOURCE_DIR}/tests/data")
    if(NOT ARG_TIMEOUT)
        set(ARG_TIMEOUT 300)
    endif()
    set(tests)
    if(ARG_FUNCTIONS)
        # Every test function of the sources (after their "private slots:") must be listed, or
        # a new one would never run.
        foreach(source IN LISTS ARG_SOURCES)
            file(READ ${source} text)
            string(FIND "${text}" "private slots:" at)
            if(at GREATER -1)
                string(SUBSTRING "${text}" ${at} -1 text)
            endif()
            string(REGEX MATCHALL "\n    void [A-Za-z0-9_]+\\(\\) {" slots "${text}")
            foreach(slot IN LISTS slots)
                string(REGEX REPLACE "^\n    void ([A-Za-z0-9_]+).*" "\\1" slot "${slot}")
                if(NOT slot IN_LIST ARG_FUNCTIONS)
                    message(FATAL_ERROR "${name}: test function ${slot} is not in FUNCTIONS")
                endif()
            endforeach()
        endforeach()
        foreach(function IN LISTS ARG_FUNCTIONS)
            add_test(NAME ${name}.${function} COMMAND ${name} ${function})
            list(APPEND tests ${name}.${function})
        endforeach()
    else()
        add_test(NAME ${name} COMMAND ${name})
        set(tests ${name})
    endif()
    set_tests_properties(${tests} PROPERTIES
        LABELS "${ARG_LABELS}"
        TIMEOUT ${ARG_TIMEOUT}
        ENVIRONMENT "QT_QPA_PLATFORM=offscreen")
endfunction()

# prisca_add_benchmark(<name> SOURCES <files...> LIBRARIES <targets...>)
# A benchmark is built with the tests but only run by `make bench` (label "benchmark").
function(prisca_add_benchmark name)
    cmake_parse_arguments(ARG "" "" "SOURCES;LIBRARIES" ${ARGN})
    add_executable(${name} ${ARG_SOURCES})
    target_link_libraries(${name} PRIVATE ${ARG_LIBRARIES})
    add_test(NAME ${name} COMMAND ${name})
    set_tests_properties(${name} PROPERTIES LABELS "benchmark" TIMEOUT 900
        ENVIRONMENT "QT_QPA_PLATFORM=offscreen")
endfunction()
