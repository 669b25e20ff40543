# pba_target_warnings(target): the project's warning set, applied per target so that
# system headers (ImGui, Assimp, GLM) never add noise. The build is kept warning-free.
function(pba_target_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor
                                           -Wconversion-null -Wno-missing-field-initializers)
  if(PBA_WARNINGS_AS_ERRORS)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()
