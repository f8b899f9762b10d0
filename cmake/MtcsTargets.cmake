# Warnings and sanitizers applied to every mtcs target.
function(mtcs_target_defaults target)
  # -Wno-restrict: GCC 12 reports false overlaps inside std::string concatenation (GCC bug 105329).
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wno-psabi -Wno-restrict)
  if(MTCS_SANITIZE)
    target_compile_options(${target} PRIVATE -fsanitize=address,undefined -fno-omit-frame-pointer
                                             $<$<CXX_COMPILER_ID:Clang>:-Wno-unknown-warning-option>)
    target_link_options(${target} PRIVATE -fsanitize=address,undefined)
  endif()
  if(MTCS_FUZZ)  # coverage for libFuzzer; the fuzz targets link the fuzzer itself
    target_compile_options(${target} PRIVATE -fsanitize=fuzzer-no-link,${MTCS_FUZZ_SANITIZERS} -fno-omit-frame-pointer
                                             -Wno-unknown-warning-option)
    target_link_options(${target} PRIVATE -fsanitize=${MTCS_FUZZ_SANITIZERS})
  endif()
endfunction()

# One module of DESIGN.md: library mtcs_NAME (alias mtcs::NAME) over include/mtcs/NAME and
# src/NAME.
#   mtcs_module(NAME SOURCES a.cpp ... [PUBLIC deps ...] [PRIVATE deps ...])
function(mtcs_module name)
  cmake_parse_arguments(M "" "" "SOURCES;PUBLIC;PRIVATE" ${ARGN})
  add_library(mtcs_${name} ${M_SOURCES})
  add_library(mtcs::${name} ALIAS mtcs_${name})
  target_include_directories(mtcs_${name} PUBLIC $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/include>
                                                $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  target_link_libraries(mtcs_${name} PUBLIC ${M_PUBLIC} PRIVATE ${M_PRIVATE})
  mtcs_target_defaults(mtcs_${name})
  if(MTCS_UNITY_BUILD)  # names private to a file must then be unique within its module
    set_target_properties(mtcs_${name} PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE 16)
  endif()
endfunction()
