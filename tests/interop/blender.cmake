# Blender 3.4 (Debian's `blender`), a real client written by others, both ways:
# - blender_exports_scenes runs make_fixtures.py: Blender builds its three-object scene and exports it
#   with its default FBX, glb and Collada settings; tst_blender_exports then imports what it wrote, as
#   tst_blender_fixtures does the committed copies, and checks every frame against Blender's own
#   evaluation (0.01° FBX and Collada, 0.2° glb).
# - blender_imports_gyre_<format>_<sample>, for fbx, glb and dae, run blender_import_gyre.py:
#   gyre-cli exports every bundled sample as FBX, glb and Collada, Blender imports each with its default
#   importer, and every object's pose at every baked time must match gyre-cli bake (0.01°, 1e-4 m),
#   its mesh standing where Gyre puts it, each action the clip's full length; FBX also with the
#   project's frame rate (glTF and Gyre's Collada store none: Blender keys them at 24 fps).
#   blender_imports_gyre_glb-spline_<sample>, for the samples with hermite tracks: the same without
#   their fits, so that the rotations go out as CUBICSPLINE samplers.
# - blender_imports_gyre_<format>_blender-empty, for fbx and glb: the same on Blender's own Empty carrying a
#   mesh object (blender_empty_and_mesh.<format> from blender_exports_scenes), which gyre-cli imports first;
#   the Empty must come back to Blender an EMPTY.
# - blender_imports_gyre_skin_<format>, for glb, fbx and dae, runs blender_skin_gyre.py: Blender's skinned bar
#   (blender_skinned_bar.glb from blender_exports_scenes) imported and exported by gyre-cli (the glb
#   validated), and imported by Blender, which must deform it at every frame as it deformed the original
#   (1e-6 m).
# - blender_writes_wrapping_spin runs wrapping_spin.py: an FBX whose object spins about Z to 530°, with Blender's
#   rotation at each key; tst_blender_euler_filter imports it with gyre-cli import --euler-filter and checks that the
#   stored angles are a continuous ramp that ends at 530° and that every key turns as Blender's (issue 23).
# scripts/install-deps.sh installs Blender with the other packages; without it these tests fail and
# say so, rather than pass unseen.
find_program(GYRE_BLENDER blender)
set(blender_exports ${CMAKE_CURRENT_BINARY_DIR}/blender-exports)
if(GYRE_BLENDER)
    set(blender_command ${GYRE_BLENDER} -b --factory-startup --python-exit-code 1 --python)
else()
    set(blender_command ${CMAKE_COMMAND} -E echo "blender is not installed: run scripts/install-deps.sh" && false)
endif()

add_test(NAME blender_exports_scenes
         COMMAND ${blender_command} ${CMAKE_CURRENT_SOURCE_DIR}/make_fixtures.py -- ${blender_exports})
set_tests_properties(blender_exports_scenes PROPERTIES LABELS interop FIXTURES_SETUP blender_exports)

add_test(NAME tst_blender_exports COMMAND tst_blender_fixtures)
set_tests_properties(tst_blender_exports PROPERTIES LABELS interop FIXTURES_REQUIRED blender_exports
    ENVIRONMENT "GYRE_BLENDER_FILES=${blender_exports};QT_QPA_PLATFORM=offscreen;LSAN_OPTIONS=suppressions=${PROJECT_SOURCE_DIR}/tests/sanitizers/lsan-assimp.supp")

set(blender_spin ${CMAKE_CURRENT_BINARY_DIR}/blender-spin)
add_test(NAME blender_writes_wrapping_spin
         COMMAND ${blender_command} ${CMAKE_CURRENT_SOURCE_DIR}/wrapping_spin.py -- ${blender_spin})
set_tests_properties(blender_writes_wrapping_spin PROPERTIES LABELS interop FIXTURES_SETUP blender_spin)
gyre_add_test(tst_blender_euler_filter LABEL interop SOURCES tst_blender_euler_filter.cpp LIBRARIES gyre_model)
target_include_directories(tst_blender_euler_filter PRIVATE ${PROJECT_SOURCE_DIR}/tests/cli)
target_compile_definitions(tst_blender_euler_filter PRIVATE GYRE_CLI_PATH="$<TARGET_FILE:gyre-cli>")
add_dependencies(tst_blender_euler_filter gyre-cli gyre-scene-worker)
set_tests_properties(tst_blender_euler_filter PROPERTIES FIXTURES_REQUIRED blender_spin)
set_property(TEST tst_blender_euler_filter APPEND PROPERTY ENVIRONMENT "GYRE_BLENDER_FILES=${blender_spin}")

file(GLOB bundled_samples ${PROJECT_SOURCE_DIR}/resources/samples/*.gyre)
foreach(sample IN LISTS bundled_samples)
    get_filename_component(name ${sample} NAME_WE)
    foreach(format IN ITEMS fbx glb dae)
        add_test(NAME blender_imports_gyre_${format}_${name}
                 COMMAND ${blender_command} ${CMAKE_CURRENT_SOURCE_DIR}/blender_import_gyre.py
                         -- ${format} $<TARGET_FILE:gyre-cli> ${sample})
        set_tests_properties(blender_imports_gyre_${format}_${name} PROPERTIES LABELS interop)
    endforeach()
    # glb-spline: the samples with hermite tracks, their fits removed, written as CUBICSPLINE samplers.
    # STRINGS, not READ: a version 3 project is binary after its first bytes, its JSON header text.
    file(STRINGS ${sample} hermite_lines REGEX "\"interpolation\": \"hermite\"")
    if(hermite_lines)
        add_test(NAME blender_imports_gyre_glb-spline_${name}
                 COMMAND ${blender_command} ${CMAKE_CURRENT_SOURCE_DIR}/blender_import_gyre.py
                         -- glb-spline $<TARGET_FILE:gyre-cli> ${sample})
        set_tests_properties(blender_imports_gyre_glb-spline_${name} PROPERTIES LABELS interop)
    endif()
endforeach()

foreach(format IN ITEMS fbx glb)
    add_test(NAME blender_imports_gyre_${format}_blender-empty
             COMMAND ${blender_command} ${CMAKE_CURRENT_SOURCE_DIR}/blender_import_gyre.py
                     -- ${format} $<TARGET_FILE:gyre-cli> ${blender_exports}/blender_empty_and_mesh.${format})
    set_tests_properties(blender_imports_gyre_${format}_blender-empty PROPERTIES LABELS interop
                         FIXTURES_REQUIRED blender_exports)
endforeach()

foreach(format IN ITEMS glb fbx dae)
    add_test(NAME blender_imports_gyre_skin_${format}
             COMMAND ${blender_command} ${CMAKE_CURRENT_SOURCE_DIR}/blender_skin_gyre.py
                     -- ${format} $<TARGET_FILE:gyre-cli> ${GYRE_NODE} ${CMAKE_CURRENT_SOURCE_DIR}/validate_gltf.mjs
                        ${GYRE_GLTF_VALIDATOR_PREFIX} ${blender_exports}/blender_skinned_bar.glb
                        ${blender_exports}/blender_skinned_bar.json)
    set_tests_properties(blender_imports_gyre_skin_${format} PROPERTIES LABELS interop
                         FIXTURES_REQUIRED "blender_exports;gltf_validator")
endforeach()
