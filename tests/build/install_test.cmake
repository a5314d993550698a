# ctest install_embedding_example: installs the build into BUILD/install-test,
# then builds and runs examples/embedding against it as a separate project.
set(prefix ${BUILD}/install-test)
file(REMOVE_RECURSE ${prefix} ${BUILD}/install-test-example)
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BUILD} --prefix ${prefix}
                RESULT_VARIABLE rc OUTPUT_QUIET)
if(rc)
  message(FATAL_ERROR "cmake --install failed (${rc})")
endif()
foreach(f bin/skipnc lib/cmake/skipnc/skipnc-config.cmake
          lib/cmake/skipnc/skipnc-config-version.cmake include/skipnc/kernel/kernel.hpp)
  if(NOT EXISTS ${prefix}/${f})
    message(FATAL_ERROR "not installed: ${f}")
  endif()
endforeach()
execute_process(COMMAND ${CMAKE_COMMAND} -S ${SOURCE}/examples/embedding
                        -B ${BUILD}/install-test-example -G ${GENERATOR}
                        -DCMAKE_CXX_COMPILER=${CXX} -DCMAKE_PREFIX_PATH=${prefix}
                        -DCMAKE_BUILD_TYPE=Release
                RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "configuring the example against the installed package failed (${rc})")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build ${BUILD}/install-test-example RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "building the example against the installed package failed (${rc})")
endif()
execute_process(COMMAND ${BUILD}/install-test-example/skipnc_embedding_example
                RESULT_VARIABLE rc OUTPUT_VARIABLE out)
message("${out}")
if(rc)
  message(FATAL_ERROR "the example built against the installed package failed (${rc})")
endif()
