# ctest install_public_headers: installs the build into BUILD/install-headers-test
# and checks that the package holds the public headers only: no stage's
# internal parts (interpreter/impl.hpp, the parser's parser_impl.hpp, the
# toml++ readers), no installed file that names toml++, every skipnc header an
# installed header includes installed too; then builds tests/build/consumer
# against it with a toml++ on the include path that stops any compile that
# includes it, and runs its kernel-only program.
set(prefix ${BUILD}/install-headers-test)
set(consumer ${BUILD}/install-headers-consumer)
file(REMOVE_RECURSE ${prefix} ${consumer})
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BUILD} --prefix ${prefix}
                RESULT_VARIABLE rc OUTPUT_QUIET)
if(rc)
  message(FATAL_ERROR "cmake --install failed (${rc})")
endif()
set(include ${prefix}/include/skipnc)
file(GLOB_RECURSE files RELATIVE ${include} ${include}/*)
if(NOT files)
  message(FATAL_ERROR "no header installed under ${include}")
endif()
foreach(f ${files})
  get_filename_component(name ${f} NAME)
  if(name MATCHES "impl\\.hpp$" OR name MATCHES "toml")
    message(FATAL_ERROR "internal header installed: ${f}")
  endif()
  file(STRINGS ${include}/${f} hits REGEX "toml\\+\\+|impl\\.hpp")
  if(hits)
    message(FATAL_ERROR "installed header ${f} names toml++ or impl.hpp: ${hits}")
  endif()
  file(STRINGS ${include}/${f} includes REGEX "^#include \"")
  foreach(line ${includes})
    if(line MATCHES "^#include \"([^\"]+)\"" AND NOT EXISTS ${include}/${CMAKE_MATCH_1})
      message(FATAL_ERROR "installed header ${f} includes ${CMAKE_MATCH_1}, which is not installed")
    endif()
  endforeach()
endforeach()
file(GLOB package ${prefix}/lib/cmake/skipnc/*.cmake)
foreach(f ${package})
  file(STRINGS ${f} hits REGEX "toml|TOML")
  if(hits)
    message(FATAL_ERROR "the package asks its users for toml++ (${f}): ${hits}")
  endif()
endforeach()
execute_process(COMMAND ${CMAKE_COMMAND} -S ${SOURCE}/tests/build/consumer -B ${consumer}
                        -G ${GENERATOR} -DCMAKE_CXX_COMPILER=${CXX}
                        -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_BUILD_TYPE=Release
                RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "configuring the consumer against the installed package failed (${rc})")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build ${consumer} RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "building the consumer against the installed package failed (${rc})")
endif()
execute_process(COMMAND ${consumer}/kernel_only RESULT_VARIABLE rc OUTPUT_VARIABLE out)
message("${out}")
if(rc OR NOT out STREQUAL "Z -1.0000\n")
  message(FATAL_ERROR "the kernel-only consumer failed (${rc}): ${out}")
endif()
