# Intel processors of the Skylake family, with the microcode that works around
# their jump erratum (JCC), do not keep in the decoded-instruction cache a
# jump that crosses or ends on a 32-byte boundary: a hot loop whose jump lands
# there runs 10-15% slower, and whether it does depends on where unrelated
# code happened to move it. Padding keeps jumps off those boundaries, so that
# a traversal's speed does not change from one build to the next for no
# reason in its own code (the machine code grows by about 3%).
option(CGOGN_ALIGN_BRANCHES "Keep jumps off 32-byte boundaries on x86-64 (stable loop speed on Intel CPUs with the JCC erratum fix)" ON)
if(CGOGN_ALIGN_BRANCHES AND CMAKE_SYSTEM_PROCESSOR MATCHES "x86_64|AMD64|amd64")
  include(CheckCXXCompilerFlag)
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
    set(_cgogn_align_flag "-Wa,-mbranches-within-32B-boundaries")
  else()
    set(_cgogn_align_flag "-mbranches-within-32B-boundaries")
  endif()
  check_cxx_compiler_flag("${_cgogn_align_flag}" CGOGN_HAS_BRANCH_ALIGNMENT)
  if(CGOGN_HAS_BRANCH_ALIGNMENT)
    add_compile_options("${_cgogn_align_flag}")
  endif()
endif()
