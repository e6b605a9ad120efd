cmake_minimum_required(VERSION 3.24)
# Fails when a C++ source differs from what the checked-in .clang-format makes of it, naming the
# files and the first lines that differ; `make format` rewrites them. The sources are the
# product's and its tests' and tools' (tests/data holds inputs, not code).
# Run by CTest as: cmake -DSOURCE_DIR=... -P check_format.cmake
find_program(CLANG_FORMAT NAMES clang-format clang-format-14)
if(NOT CLANG_FORMAT)
    message(FATAL_ERROR "clang-format is not installed (make test installs it: scripts/install-deps.sh)")
endif()
set(sources)
foreach(dir IN ITEMS app core sim devices rigsim rig tools tests)
    file(GLOB_RECURSE found "${SOURCE_DIR}/${dir}/*.h" "${SOURCE_DIR}/${dir}/*.cpp")
    list(FILTER found EXCLUDE REGEX "/tests/data/")
    list(APPEND sources ${found})
endforeach()
list(LENGTH sources count)
execute_process(COMMAND ${CLANG_FORMAT} --dry-run --Werror --style=file ${sources}
                WORKING_DIRECTORY "${SOURCE_DIR}"
                RESULT_VARIABLE result ERROR_VARIABLE problems OUTPUT_QUIET)
if(NOT result EQUAL 0)
    string(REGEX MATCHALL "[^\n]*: error: code should be clang-formatted[^\n]*" lines "${problems}")
    list(LENGTH lines wrong)
    list(SUBLIST lines 0 20 shown)
    string(REPLACE ";" "\n" shown "${shown}")
    message(FATAL_ERROR "${wrong} place(s) in the sources are not as .clang-format has them "
                        "(make format fixes them); the first:\n${shown}")
endif()
message(STATUS "${count} sources are formatted as .clang-format says")
