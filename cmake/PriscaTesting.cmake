# prisca_add_test(<name> SOURCES <files...> LIBRARIES <targets...> LABELS <labels...>
#                  [TIMEOUT <seconds>] [EACH_FUNCTION] [ENVIRONMENT <VAR=value...>])
# One QtTest executable registered with CTest; tests always run offscreen. With EACH_FUNCTION,
# each test function of the sources (the `    void name() {` lines after "private slots:") is
# its own CTest test (<name>.<function>), so that the minutes-long ones run side by side under
# `ctest -j`; a source's change re-runs the configure, so a new function is registered.
function(prisca_add_test name)
    cmake_parse_arguments(ARG "EACH_FUNCTION" "TIMEOUT" "SOURCES;LIBRARIES;LABELS;ENVIRONMENT"
                          ${ARGN})
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
    if(ARG_EACH_FUNCTION)
        foreach(source IN LISTS ARG_SOURCES)
            set(path ${CMAKE_CURRENT_SOURCE_DIR}/${source})
            set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${path})
            file(READ ${path} text)
            string(FIND "${text}" "private slots:" at)
            if(at EQUAL -1)
                message(FATAL_ERROR "${name}: ${source} has no \"private slots:\"")
            endif()
            string(SUBSTRING "${text}" ${at} -1 text)
            string(REGEX MATCHALL "\n    void [A-Za-z0-9_]+\\(\\) {" slots "${text}")
            foreach(slot IN LISTS slots)
                string(REGEX REPLACE "^\n    void ([A-Za-z0-9_]+).*" "\\1" function "${slot}")
                add_test(NAME ${name}.${function} COMMAND ${name} ${function})
                list(APPEND tests ${name}.${function})
            endforeach()
        endforeach()
        if(NOT tests)
            message(FATAL_ERROR "${name}: no test function found in ${ARG_SOURCES}")
        endif()
    else()
        add_test(NAME ${name} COMMAND ${name})
        set(tests ${name})
    endif()
    set(environment QT_QPA_PLATFORM=offscreen ${ARG_ENVIRONMENT})
    set_tests_properties(${tests} PROPERTIES
        LABELS "${ARG_LABELS}"
        TIMEOUT ${ARG_TIMEOUT}
        ENVIRONMENT "${environment}")
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
