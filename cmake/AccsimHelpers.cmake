# Warnings (as errors) and sanitizers for accsim's own targets only.
function(accsim_target_defaults target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wno-unused-parameter)
  if(ACCSIM_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
  if(ACCSIM_SANITIZE)
    # GCC 12 reports false maybe-uninitialized warnings inside <regex> when
    # instrumented; they are not ours to fix.
    if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
      target_compile_options(${target} PRIVATE -Wno-maybe-uninitialized)
    endif()
    target_compile_options(${target} PRIVATE -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined)
    target_link_options(${target} PRIVATE -fsanitize=address,undefined)
  endif()
endfunction()

# accsim_add_library(NAME <short> SOURCES ... DEPS ...) -> target accsim_<short>, alias accsim::<short>
function(accsim_add_library)
  cmake_parse_arguments(ARG "" "NAME" "SOURCES;DEPS;PRIVATE_DEPS" ${ARGN})
  set(target accsim_${ARG_NAME})
  add_library(${target} STATIC ${ARG_SOURCES})
  add_library(accsim::${ARG_NAME} ALIAS ${target})
  target_include_directories(${target} PUBLIC ${CMAKE_CURRENT_SOURCE_DIR}/include)
  target_link_libraries(${target} PUBLIC ${ARG_DEPS} PRIVATE ${ARG_PRIVATE_DEPS})
  accsim_target_defaults(${target})
  if(ACCSIM_SANITIZE)
    target_link_options(${target} INTERFACE -fsanitize=address,undefined)
  endif()
endfunction()

# accsim_add_gtest(<name> SOURCES ... DEPS ...): one GoogleTest binary, tests discovered by ctest.
function(accsim_add_gtest name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPS" ${ARGN})
  add_executable(${name} ${ARG_SOURCES})
  target_link_libraries(${name} PRIVATE ${ARG_DEPS} GTest::gtest_main GTest::gmock)
  target_compile_definitions(${name} PRIVATE
    ACCSIM_SOURCE_DIR="${PROJECT_SOURCE_DIR}"
    ACCSIM_SHARED_DIR="${PROJECT_SOURCE_DIR}/../shared")
  accsim_target_defaults(${name})
  gtest_discover_tests(${name} DISCOVERY_TIMEOUT 60 PROPERTIES TIMEOUT 300)
endfunction()
