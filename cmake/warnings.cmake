# Warnings for the project's own targets (not propagated to users).
function(cgogn_set_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic)
  if(CGOGN_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()
option(CGOGN_WERROR "Treat warnings as errors" OFF)
