# Installs the npm package gltf-validator, version VERSION, under PREFIX with NPM, unless that
# version is there already: a second run needs no network.
#   cmake -DNPM=/usr/bin/npm -DPREFIX=<dir> -DVERSION=<version> -P install_gltf_validator.cmake
set(manifest "${PREFIX}/node_modules/gltf-validator/package.json")
if(EXISTS "${manifest}")
    file(READ "${manifest}" json)
    string(JSON installed ERROR_VARIABLE no_version GET "${json}" version)
    if(installed STREQUAL VERSION)
        message(STATUS "gltf-validator ${VERSION} is installed in ${PREFIX}")
        return()
    endif()
endif()
execute_process(COMMAND "${NPM}" install --prefix "${PREFIX}" --no-audit --no-fund --save-exact
                        "gltf-validator@${VERSION}"
                RESULT_VARIABLE status)
if(NOT status EQUAL 0 OR NOT EXISTS "${manifest}")
    message(FATAL_ERROR "npm could not install gltf-validator@${VERSION} into ${PREFIX} (status ${status}); "
                        "it needs the npm registry once, then runs from the build tree")
endif()
