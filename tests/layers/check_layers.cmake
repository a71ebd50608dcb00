# The layer rule of DESIGN.md, checked on every #include of the project's own headers: each folder of
# src/ may include its own headers and those of the layers above it, nothing else. (Qt and widget
# headers need no check here: a library that does not link Qt, or Qt's Widgets, cannot find them.)
#   cmake -DSOURCE_DIR=<folder holding src/> -P check_layers.cmake
# Fails naming every include that breaks the rule, as file:line.

cmake_minimum_required(VERSION 3.25)

if(NOT SOURCE_DIR)
    message(FATAL_ERROR "usage: cmake -DSOURCE_DIR=<folder holding src/> -P check_layers.cmake")
endif()

# Each layer and what it may include, top of DESIGN.md's table first. The programs come last:
# gyre (app), gyre-cli (cli) and gyre-scene-worker (worker), which runs Assimp out of process.
set(allowed_core core)
set(allowed_fit core fit)
set(allowed_model core fit model)
set(allowed_io core model io)
set(allowed_jobs core fit model io jobs)
set(allowed_samples core fit model io jobs samples)
set(allowed_app core fit model io jobs app)
set(allowed_cli core fit model io jobs cli)
set(allowed_worker core model io worker)
set(layers core fit model io jobs samples app cli worker)

set(breaches "")
set(checked 0)
file(GLOB layer_folders LIST_DIRECTORIES true RELATIVE "${SOURCE_DIR}/src" "${SOURCE_DIR}/src/*")
foreach(folder IN LISTS layer_folders)
    if(IS_DIRECTORY "${SOURCE_DIR}/src/${folder}" AND NOT folder IN_LIST layers)
        list(APPEND breaches "src/${folder}: a folder that is no layer of DESIGN.md")
    endif()
endforeach()

foreach(layer IN LISTS layers)
    file(GLOB_RECURSE sources "${SOURCE_DIR}/src/${layer}/*.h" "${SOURCE_DIR}/src/${layer}/*.cpp")
    foreach(source IN LISTS sources)
        file(STRINGS "${source}" lines)
        set(number 0)
        foreach(line IN LISTS lines)
            math(EXPR number "${number} + 1")
            if(line MATCHES "^[ \t]*#[ \t]*include[ \t]*\"([a-z_]+)/")
                math(EXPR checked "${checked} + 1")
                set(included "${CMAKE_MATCH_1}")
                if(NOT included IN_LIST allowed_${layer})
                    file(RELATIVE_PATH shown "${SOURCE_DIR}" "${source}")
                    list(APPEND breaches "${shown}:${number}: ${layer} includes ${included}, which it may not")
                endif()
            endif()
        endforeach()
    endforeach()
endforeach()

if(breaches)
    list(JOIN breaches "\n" report)
    message(FATAL_ERROR "The layer rule is broken:\n${report}")
endif()
message(STATUS "${checked} includes of the project's headers keep the layer rule")
