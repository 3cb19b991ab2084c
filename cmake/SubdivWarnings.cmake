# subdiv_set_warnings(target): the project's warning set, as errors when
# SUBDIV_WARNINGS_AS_ERRORS is on (CI turns it on).
function(subdiv_set_warnings target)
  target_compile_options(${target} PRIVATE
    -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor -Woverloaded-virtual
    -Wcast-align -Wdouble-promotion -Wformat=2 -Wimplicit-fallthrough)
  # GCC 12 reports std::string concatenation in optimised builds as
  # overlapping memcpy (a known false positive, GCC bug 105329).
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_CXX_COMPILER_VERSION VERSION_LESS 13)
    target_compile_options(${target} PRIVATE -Wno-restrict)
  endif()
  if(SUBDIV_WARNINGS_AS_ERRORS)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()
