# Warnings and sanitizers applied to every mtcs target through mtcs_target_defaults().
function(mtcs_target_defaults target)
  # -Wno-restrict: GCC 12 reports false overlaps inside std::string concatenation (GCC bug 105329).
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wno-psabi -Wno-restrict)
  if(MTCS_SANITIZE)
    target_compile_options(${target} PRIVATE -fsanitize=address,undefined -fno-omit-frame-pointer)
    target_link_options(${target} PRIVATE -fsanitize=address,undefined)
  endif()
endfunction()
