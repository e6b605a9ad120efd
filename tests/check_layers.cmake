cmake_minimum_required(VERSION 3.24)
# Fails when a layer's sources include a layer above or beside it: core includes only core/,
# sim only core/ and sim/, devices only core/ and devices/, rigsim (the rig with no hardware)
# those and itself, rig (the rig session) all of those (app/ may include them all).
# Run by CTest as: cmake -DSOURCE_DIR=... -P check_layers.cmake
set(rules "core:sim/,devices/,rigsim/,rig/,app/" "sim:devices/,rigsim/,rig/,app/"
          "devices:sim/,rigsim/,rig/,app/" "rigsim:rig/,app/" "rig:app/")
set(checked 0)
foreach(rule IN LISTS rules)
    string(REPLACE ":" ";" parts "${rule}")
    list(GET parts 0 layer)
    list(GET parts 1 forbidden)
    string(REPLACE "," ";" forbidden "${forbidden}")
    file(GLOB_RECURSE sources "${SOURCE_DIR}/${layer}/*.h" "${SOURCE_DIR}/${layer}/*.cpp")
    foreach(src IN LISTS sources)
        math(EXPR checked "${checked} + 1")
        file(STRINGS "${src}" includes REGEX "^[ \t]*#[ \t]*include[ \t]*[\"<]")
        foreach(line IN LISTS includes)
            foreach(prefix IN LISTS forbidden)
                if(line MATCHES "#[ \t]*include[ \t]*[\"<](\\.\\./)*${prefix}")
                    message(FATAL_ERROR "${src}: '${line}': the ${layer} layer may not include ${prefix}")
                endif()
            endforeach()
        endforeach()
    endforeach()
endforeach()
# The method declarations (sim/methods/) are the catalog's: everything else reaches a method
# through sim/MethodCatalog.h.
file(GLOB_RECURSE outside "${SOURCE_DIR}/core/*.[ch]*" "${SOURCE_DIR}/devices/*.[ch]*"
     "${SOURCE_DIR}/rigsim/*.[ch]*" "${SOURCE_DIR}/rig/*.[ch]*" "${SOURCE_DIR}/app/*.[ch]*"
     "${SOURCE_DIR}/tools/*.[ch]*" "${SOURCE_DIR}/tests/*.[ch]*")
foreach(src IN LISTS outside)
    file(STRINGS "${src}" includes REGEX "^[ \t]*#[ \t]*include[ \t]*\"sim/methods/")
    if(includes)
        message(FATAL_ERROR "${src}: '${includes}': sim/methods/ is the catalog's own; use sim/MethodCatalog.h")
    endif()
endforeach()
message(STATUS "${checked} sources of core, sim, devices, rigsim and rig include only their own layers and below")
